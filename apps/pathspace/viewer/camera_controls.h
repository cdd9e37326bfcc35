// Camera motion of `pathspace view` (pbrt-v4 --interactive's conventions, docs/viewer.md): steps in
// the camera's own frame, turns about its up and right axes, and the CLI options that reproduce a view.
#pragma once

#include <string>

#include "pathspace/camera/perspective_camera.h"

namespace pathspace::viewer {

// Moves the camera by right, up and forward steps of `step` scene units each.
void move_camera(PerspectiveCamera* camera, double right, double up, double forward, float step);
// Turns the camera by yaw degrees about its up axis, then pitch degrees about its right axis; the
// axes stay unit and orthogonal.
void turn_camera(PerspectiveCamera* camera, double yaw_degrees, double pitch_degrees);
// "--camera-pos x,y,z --camera-target x,y,z --camera-up x,y,z --fov F": the render options of this view.
std::string camera_options(const PerspectiveCamera& camera);

}  // namespace pathspace::viewer
