// pathspace.Scene: a built-in or loaded scene with its camera, and the acceleration structure built
// once for all of its renders. Changing the camera or the light selection replaces the held Scene by
// a changed copy, so that a render going on in another thread keeps the scene it started with; the
// acceleration structure is shared by the copies, since only the geometry enters it.
#pragma once

#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "pathspace/accel/accel.h"
#include "pathspace/scene/scene.h"

namespace pathspace::python {

class PyScene {
 public:
  PyScene(Scene scene, std::string label, std::string file, int file_spp, std::vector<std::string> warnings);

  // The scene as it is now (a render keeps this one, whatever happens to the PyScene later).
  std::shared_ptr<const Scene> scene() const { return scene_; }
  // The acceleration structure, built on first use from `current` (a scene() this PyScene returned:
  // they all share the geometry). Thread-safe; call it without the GIL.
  std::shared_ptr<const Accel> accel(const std::shared_ptr<const Scene>& current);

  // Replaces the camera (validated by the caller) or the light selection.
  void set_camera(const PerspectiveCamera& camera);
  void set_light_selection(LightSelection selection);

  const std::string& label() const { return label_; }  // the built-in's name or the file's path
  const std::string& file() const { return file_; }    // empty for a built-in scene
  int file_spp() const { return file_spp_; }            // the file's samples per pixel, 0: none
  const std::vector<std::string>& warnings() const { return warnings_; }

 private:
  std::shared_ptr<const Scene> scene_;
  std::string label_, file_;
  int file_spp_ = 0;
  std::vector<std::string> warnings_;
  std::mutex accel_mutex_;
  std::shared_ptr<const Accel> accel_;  // keeps the Scene it was built from alive (its arrays are read)
};

}  // namespace pathspace::python
