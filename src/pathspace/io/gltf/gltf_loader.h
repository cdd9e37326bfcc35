// glTF 2.0 scenes (.gltf with external or data-uri buffers, binary .glb) through tinygltf: the node
// hierarchy with meshes, the first perspective camera, KHR_lights_punctual and the materials of
// gltf_materials.h. Units are taken 1:1 (metres; candela, lux and nits as our intensity, irradiance
// and radiance). Unsupported features are warnings naming the glTF element; malformed files are a
// pathspace::Error naming the file (docs/scene-files.md, "glTF").
#pragma once

#include <string>

#include "pathspace/io/load_warnings.h"
#include "pathspace/io/scene_loader.h"

namespace pathspace::gltf {

// Loads and finalises the scene of a .gltf or .glb file (the format follows the content: GLB files
// start with "glTF"): with animations, the scene at 0 s of the first (gltf_animation.h).
Scene load_gltf_file(const std::string& path, const SceneLoadOptions& options, LoadWarnings* warnings);

}  // namespace pathspace::gltf
