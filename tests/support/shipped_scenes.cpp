// Shipped scene paths and OBJ cameras (see shipped_scenes.h). The cameras repeat the command lines
// in the scenes' OBJ comments and docs/scene-files.md.
#include "support/shipped_scenes.h"

#include <stdexcept>

namespace pathspace::testing {

std::string shipped_scenes_dir() { return PATHSPACE_SCENES_DIR; }

std::vector<ShippedScene> shipped_scenes() {
  ShippedScene caustic{"glass-caustic", {"scene.pbrt", "scene.xml", "scene.obj"}, {}};
  caustic.obj_camera.camera_position = Vec3(0.8f, 1.6f, 3.2f);
  caustic.obj_camera.camera_target = Vec3(0.f, 0.3f, 0.f);
  caustic.obj_camera.camera_up = Vec3(0.f, 1.f, 0.f);
  caustic.obj_camera.fov_degrees = 40.f;
  ShippedScene room{"textured-room", {"scene.pbrt", "scene.xml", "scene.obj"}, {}};
  room.obj_camera.camera_position = Vec3(0.f, 1.2f, 1.8f);
  room.obj_camera.camera_target = Vec3(0.f, 1.1f, -2.f);
  room.obj_camera.camera_up = Vec3(0.f, 1.f, 0.f);
  room.obj_camera.fov_degrees = 65.f;
  const ShippedScene fog{"fog-room", {"scene.pbrt", "scene.xml"}, {}};  // media: no OBJ form
  const ShippedScene lamp{"fog-lamp", {"scene.pbrt", "scene.xml"}, {}};
  return {caustic, room, fog, lamp};
}

const ShippedScene& shipped_scene(const std::string& name) {
  static const std::vector<ShippedScene> all = shipped_scenes();
  for (const ShippedScene& s : all)
    if (s.name == name) return s;
  throw std::invalid_argument("no shipped scene " + name);
}

Scene load_shipped(const ShippedScene& s, const std::string& form, int width, int height, std::vector<std::string>* warnings) {
  SceneLoadOptions o = form.ends_with(".obj") ? s.obj_camera : SceneLoadOptions{};
  o.width = width;
  o.height = height;
  return load_scene(shipped_scenes_dir() + "/" + s.name + "/" + form, o, warnings);
}

}  // namespace pathspace::testing
