// The host-side owner of a scene's environment image: linear RGB texels (row 0 at the top), the
// mapping, the light-to-world axes, and (after prepare()) the importance-sampling distribution.
// Scene::view() exposes it as an EnvironmentMapView (lights/environment_map.h).
#pragma once

#include <string>
#include <vector>

#include "pathspace/lights/environment_map.h"

namespace pathspace {

class EnvironmentImage {
 public:
  std::string name;  // file name, for messages
  int width = 0, height = 0;
  std::vector<Rgb> texels;
  EnvironmentMapping mapping = EnvironmentMapping::lat_long;
  Vec3 axis_x{1.f, 0.f, 0.f}, axis_y{0.f, 1.f, 0.f}, axis_z{0.f, 0.f, 1.f};  // light axes in world

  bool empty() const { return texels.empty(); }
  // Validates, orthonormalises the axes and builds the distribution. Throws pathspace::Error.
  void prepare();
  // Mean image value over the sphere of directions (for power-proportional light selection).
  Rgb sphere_mean() const { return sphere_mean_; }
  EnvironmentMapView view() const;

 private:
  Piecewise2D distribution_;
  Rgb sphere_mean_;
  float max_texel_ = 0.f;
};

}  // namespace pathspace
