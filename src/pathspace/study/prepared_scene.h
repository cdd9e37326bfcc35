// PreparedScene: a scene of an experiment ready to render cells on: geometry and acceleration
// structure (shared by every RenderSession of the scene) and the reference image the cells are
// measured against. SceneSummary is what the outputs keep of it once it is released.
#pragma once

#include <memory>
#include <string>

#include "pathspace/film/image.h"
#include "pathspace/study/experiment.h"
#include "pathspace/study/record.h"

namespace pathspace {
class Accel;
class Scene;
}  // namespace pathspace

namespace pathspace::study {

struct SceneSummary {
  std::string id, name;  // built-in: "bs_c", "cornell-box"; file: its stem and path
  int width = 0, height = 0;
  size_t light_count = 0;
  // integrator, time_budget_s, time_s, iterations, seed, noise_rel_mse, image_png, image_exr (rendered),
  // or image_file and variance_file (read).
  Record reference;
  std::string reference_png;  // relative to the output folder; empty when none was written
};

struct PreparedScene {
  SceneSummary summary;
  std::shared_ptr<const Scene> scene;
  std::shared_ptr<const Accel> accel;
  Image reference;
  Image reference_variance;  // empty when the reference has none

  const std::string& id() const { return summary.id; }
};

// The reference's own relMSE (its variance of the mean relative to its value): the floor below which
// no run's error can be measured.
double reference_noise(const Image& reference, const Image& variance);

// Builds (or loads) the scene at spec's size and its acceleration structure; no reference yet.
PreparedScene load_prepared_scene(const SceneSpec& spec);

}  // namespace pathspace::study
