// An animation: the scene at a time (animated built-ins move their lights and objects, glTF files
// their animated nodes; other scene files are the same at every time) and how the camera moves,
// sampled at frames of 1 / fps seconds. Frame f is a pure function of f (docs/animation.md).
#pragma once

#include <cstdint>
#include <functional>

#include "pathspace/camera/camera_animation.h"
#include "pathspace/scene/scene.h"

namespace pathspace {

struct Animation {
  double fps = 30.0;
  // The finalised scene `seconds` into the animation, its camera before the camera motion below.
  std::function<Scene(double seconds)> scene_at;
  CameraPath camera_path;             // empty: the scene's own camera
  float orbit_degrees_per_frame = 0;  // about the axis of the camera's up vector through the scene centre

  double seconds_of(uint64_t frame) const { return double(frame) / fps; }
  // Throws pathspace::Error when the camera of the frame is degenerate (an interpolated up vector
  // parallel to the view direction).
  Scene at_frame(uint64_t frame) const;
};

}  // namespace pathspace
