#include "pathspace/scene/animation.h"

#include <cmath>

#include "pathspace/base/error.h"

namespace pathspace {

namespace {
bool finite(const Vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }
}  // namespace

Scene Animation::at_frame(uint64_t frame) const {
  const double seconds = seconds_of(frame);
  Scene scene = scene_at(seconds);
  PerspectiveCamera& c = scene.camera;
  if (!camera_path.keys.empty()) c = camera_at_keyframe(c, camera_path.at(seconds));
  // The orbit turns about the camera's own up axis through the scene's centre, so a camera path and
  // an orbit compose (the orbit last).
  if (orbit_degrees_per_frame != 0.f)
    c = orbit_camera(c, scene.bounds().center, c.up, float(std::fmod(double(orbit_degrees_per_frame) * double(frame), 360.0)));
  if (!finite(c.position) || !finite(c.forward) || !finite(c.right) || !finite(c.up))
    throw Error("frame " + std::to_string(frame) + ": the camera is degenerate (its up vector is parallel to the view direction)");
  return scene;
}

}  // namespace pathspace
