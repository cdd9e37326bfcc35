// How the camera moves through an animation (2021 paper sec. 3.4: the table is reused across frames
// while the camera moves): keyframes interpolated linearly in time (--camera-path FILE, its format in
// docs/animation.md), and a rigid orbit about the scene's centre (--orbit DEGREES_PER_FRAME).
#pragma once

#include <vector>

#include "pathspace/camera/perspective_camera.h"

namespace pathspace {

struct CameraKeyframe {
  double time = 0.0;  // seconds
  Vec3 position, target;
  Vec3 up{0.f, 1.f, 0.f};
  float fov_degrees = 0.f;  // of the shorter image axis; 0: the scene camera's
};

// Keyframes in strictly increasing time; before the first and after the last the camera holds still.
struct CameraPath {
  std::vector<CameraKeyframe> keys;

  // Position, target, up and field of view interpolated linearly between the two keyframes around t.
  CameraKeyframe at(double time) const;
};

// The camera of `base` (its resolution and lens) placed at the keyframe: looking from its position
// at its target, the field of view of the shorter image axis set when the keyframe has one.
PerspectiveCamera camera_at_keyframe(const PerspectiveCamera& base, const CameraKeyframe& key);

// `camera` turned rigidly by `degrees` about the axis through `centre` along `axis` (right-handed):
// position and orientation rotate together, so the view of the centre is kept.
PerspectiveCamera orbit_camera(const PerspectiveCamera& camera, const Vec3& centre, const Vec3& axis, float degrees);

}  // namespace pathspace
