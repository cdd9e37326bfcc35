// glTF scene loading (see gltf_loader.h): the scene at 0 s of gltf_animation.h, which parses the
// file, walks the default scene's node trees, then sets camera and lights and finalises. Without a
// camera the view frames the bounds as for OBJ; without light sources (emissive materials alone do
// not count) a white environment lights the scene (warning), as glTF viewers do.
#include "pathspace/io/gltf/gltf_loader.h"

#include "pathspace/io/gltf/gltf_animation.h"

namespace pathspace::gltf {

Scene load_gltf_file(const std::string& path, const SceneLoadOptions& options, LoadWarnings* warnings) {
  return GltfAnimation(path, options, warnings).initial_scene();
}

}  // namespace pathspace::gltf
