#include "py_scene.h"

namespace pathspace::python {

PyScene::PyScene(Scene scene, std::string label, std::string file, int file_spp, std::vector<std::string> warnings)
    : scene_(std::make_shared<const Scene>(std::move(scene))),
      label_(std::move(label)),
      file_(std::move(file)),
      file_spp_(file_spp),
      warnings_(std::move(warnings)) {}

std::shared_ptr<const Accel> PyScene::accel(const std::shared_ptr<const Scene>& current) {
  std::lock_guard<std::mutex> lock(accel_mutex_);
  if (!accel_) {
    // Embree reads the geometry arrays of the Scene it was built from: the accel's owner keeps it.
    struct Built {
      std::shared_ptr<const Scene> scene;
      Accel accel;
      explicit Built(std::shared_ptr<const Scene> s) : scene(std::move(s)), accel(*scene) {}
    };
    auto built = std::make_shared<const Built>(current);
    accel_ = std::shared_ptr<const Accel>(built, &built->accel);
  }
  return accel_;
}

void PyScene::set_camera(const PerspectiveCamera& camera) {
  auto changed = std::make_shared<Scene>(*scene_);
  changed->camera = camera;
  changed->camera_moves = false;  // a camera placed from Python stands still, as with --camera-pos
  scene_ = std::move(changed);
}

void PyScene::set_light_selection(LightSelection selection) {
  auto changed = std::make_shared<Scene>(*scene_);
  changed->light_selection = selection;
  changed->finalize();  // the light sampler's weights follow the selection
  scene_ = std::move(changed);
}

}  // namespace pathspace::python
