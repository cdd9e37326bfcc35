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
  // A camera path places the camera absolutely: the file's own camera motion within a frame (motion
  // blur, scene/motion.h) does not compose with it, so the camera stands still within the frame.
  if (!camera_path.keys.empty()) {
    c = camera_at_keyframe(c, camera_path.at(seconds));
    scene.camera_moves = false;
  }
  // The orbit turns about the camera's own up axis through the scene's centre, so a camera path and
  // an orbit compose (the orbit last); a camera that moves within the frame is turned at both ends.
  if (orbit_degrees_per_frame != 0.f) {
    const Vec3 centre = scene.bounds().center, axis = c.up;
    const float degrees = float(std::fmod(double(orbit_degrees_per_frame) * double(frame), 360.0));
    if (scene.camera_moves) {
      PerspectiveCamera end = c;
      end.position = scene.camera_end.position;
      end.forward = scene.camera_end.forward;
      end.right = scene.camera_end.right;
      end.up = scene.camera_end.up;
      scene.camera_end = orbit_camera(end, centre, axis, degrees).pose();
    }
    c = orbit_camera(c, centre, axis, degrees);
  }
  if (!finite(c.position) || !finite(c.forward) || !finite(c.right) || !finite(c.up))
    throw Error("frame " + std::to_string(frame) + ": the camera is degenerate (its up vector is parallel to the view direction)");
  return scene;
}

}  // namespace pathspace
