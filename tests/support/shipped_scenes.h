// The shipped test scenes (scenes/, docs/scene-files.md "Shipped test scenes") for the tests: the
// path of each form and the load options that give the OBJ forms their camera (the command line in
// the scene's comments).
#pragma once

#include <string>
#include <vector>

#include "pathspace/io/scene_loader.h"

namespace pathspace::testing {

struct ShippedScene {
  std::string name;                // folder under scenes/
  std::vector<std::string> forms;  // scene.pbrt, scene.xml, scene.obj
  SceneLoadOptions obj_camera;     // --camera-pos/--camera-target/--camera-up/--fov of the OBJ form
};

std::string shipped_scenes_dir();
std::vector<ShippedScene> shipped_scenes();
const ShippedScene& shipped_scene(const std::string& name);

// Loads one form at width x height (the OBJ form with obj_camera); the warnings go to *warnings.
Scene load_shipped(const ShippedScene& s, const std::string& form, int width, int height, std::vector<std::string>* warnings);

}  // namespace pathspace::testing
