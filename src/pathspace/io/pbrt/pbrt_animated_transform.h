// pbrt-v4's animated transforms (ActiveTransform StartTime / EndTime, TransformTimes): a transform
// at a time between the start and the end one, as pbrt-v4's AnimatedTransform interpolates it
// (Shoemake and Duff 1992): each matrix is split into a translation T, a rotation R (polar
// decomposition) and the remaining stretch S, and the rotations are interpolated by quaternion
// slerp, T and S linearly. Host only, double precision.
#pragma once

#include "pathspace/io/pbrt/pbrt_transform.h"

namespace pathspace::pbrt {

// Above this rotation between shutter open and close, vertices moving on straight lines (Embree's
// two time steps, scene/motion.h) visibly cut the arcs that pbrt-v4 and Mitsuba follow: both loaders
// warn.
inline constexpr double kMaxLinearRotationDegrees = 10.0;
// Point-like lights move but keep one orientation: a turn larger than this while the shutter is open
// (beyond rounding) is reported by both loaders.
inline constexpr double kLightTurnWarningDegrees = 0.1;

struct Quaternion {
  double w = 1.0, x = 0.0, y = 0.0, z = 0.0;
};

struct DecomposedTransform {
  double t[3] = {0.0, 0.0, 0.0};
  Quaternion r;
  double s[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
};

// M = T R S (false when the upper 3x3 is singular or the decomposition does not converge).
bool decompose_transform(const Mat4& m, DecomposedTransform* out);
Mat4 compose_transform(const DecomposedTransform& d);

// The transform at fraction `s` in [0, 1] of the way from `start` to `end`; exactly `start` at 0 and
// `end` at 1. False when either matrix cannot be decomposed.
bool interpolate_transform(const Mat4& start, const Mat4& end, double s, Mat4* out);

// The transform at `time` of one that is `start` at time t0 and `end` at time t1 (t0 <= t1), as
// pbrt-v4's AnimatedTransform and Mitsuba's keys have it: `start` up to t0, `end` from t1 on.
bool animated_transform_at(const Mat4& start, const Mat4& end, double t0, double t1, double time, Mat4* out);

// The angle in degrees of the rotation that takes start's rotation part to end's (0 when either
// cannot be decomposed).
double rotation_between_degrees(const Mat4& start, const Mat4& end);

}  // namespace pathspace::pbrt
