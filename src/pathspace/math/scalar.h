// Scalar helpers and constants shared by host and device code.
// Names avoid std:: ones (lerp, clamp) so argument-dependent lookup never picks the wrong one
// under nvcc (docs/toolchain.md).
#pragma once

#include <cmath>
#include <cstdint>

#include "pathspace/base/platform.h"

namespace pathspace {

using std::isfinite;
using std::isinf;

inline constexpr float kPi = 3.14159265358979323846f;
inline constexpr float kTwoPi = 6.28318530717958647692f;
inline constexpr float kFourPi = 12.5663706143591729539f;
inline constexpr float kInvPi = 0.31830988618379067154f;
inline constexpr float kInvTwoPi = 0.15915494309189533577f;
inline constexpr float kInvFourPi = 0.07957747154594766788f;
inline constexpr float kInfinity = INFINITY;
// Largest float below 1: the upper end of every canonical random number.
inline constexpr float kOneMinusEpsilon = 0x1.fffffep-1f;

PS_INLINE float sqr(float x) { return x * x; }
PS_INLINE float clamp_to(float x, float lo, float hi) { return x < lo ? lo : (x > hi ? hi : x); }
PS_INLINE float mix_linear(float a, float b, float t) { return a + (b - a) * t; }
PS_INLINE float safe_sqrt(float x) { return sqrtf(x > 0.f ? x : 0.f); }
PS_INLINE float safe_acos(float x) { return acosf(clamp_to(x, -1.f, 1.f)); }
PS_INLINE float max_of(float a, float b) { return a > b ? a : b; }
PS_INLINE float min_of(float a, float b) { return a < b ? a : b; }
PS_INLINE int max_int(int a, int b) { return a > b ? a : b; }
PS_INLINE int min_int(int a, int b) { return a < b ? a : b; }
PS_INLINE bool is_finite(float x) { return isfinite(x); }
PS_INLINE float radians(float deg) { return deg * (kPi / 180.f); }

}  // namespace pathspace
