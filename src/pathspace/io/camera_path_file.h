// Reads a camera path (--camera-path FILE): JSON keyframes of time, position, target, up and field of
// view (docs/animation.md). Throws pathspace::Error naming the file, with line:column for JSON syntax
// errors and the keyframe for wrong values.
#pragma once

#include <string>

#include "pathspace/camera/camera_animation.h"

namespace pathspace {

CameraPath read_camera_path(const std::string& path);
// The same from text (`name` is the file name in messages).
CameraPath parse_camera_path(const std::string& text, const std::string& name);

}  // namespace pathspace
