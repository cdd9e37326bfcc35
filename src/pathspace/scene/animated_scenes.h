// Built-in animated scenes (listed in builtin_scenes.h): what the temporal reuse of the hashed filter
// (2021 paper sec. 3.4) is tested on. Each is a pure function of the time in seconds; the camera
// stays where SmallVCM's Cornell box puts it (--orbit and --camera-path move it).
#pragma once

#include "pathspace/scene/scene.h"

namespace pathspace {

inline constexpr double kMovingScenePeriod = 4.0;   // seconds for one sweep or lap
inline constexpr float kMovingLightAmplitude = 0.7f;  // the light box's largest offset along x

// The Cornell box with a diffuse sphere (radius 0.5) standing on the floor and its ceiling light
// sweeping along x (fig. 9's moving light and moving shadow): offset -kMovingLightAmplitude *
// cos(2 pi t / kMovingScenePeriod), so it moves fastest at a quarter period.
Scene make_moving_light_scene(int width, int height, double seconds);
Scene make_moving_light_frame0(int width, int height);
// The empty Cornell box with a diffuse sphere (radius 0.4) circling on the floor once a period.
Scene make_moving_sphere_scene(int width, int height, double seconds);
Scene make_moving_sphere_frame0(int width, int height);

}  // namespace pathspace
