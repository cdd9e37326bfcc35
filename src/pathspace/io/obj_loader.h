// Wavefront OBJ + MTL scenes through tinyobjloader (Debian libtinyobjloader-dev). Faces are
// triangulated; MTL materials map onto pathspace's standard material (Kd diffuse, Ks + Ns Phong,
// illum 5/7 or Ni with d < 1 glass, Ke area emission). OBJ has no camera: it comes from the load
// options or frames the bounding box. Unsupported statements become warnings with file:line.
#pragma once

#include <string>

#include "pathspace/io/load_warnings.h"
#include "pathspace/io/scene_loader.h"

namespace pathspace {

// Appends the OBJ's triangles, materials and emitters to *scene (camera and finalize are the caller's).
void load_obj_into(const std::string& path, LoadWarnings* warnings, Scene* scene);

}  // namespace pathspace
