// Display encoding: the exact piecewise sRGB transfer function (IEC 61966-2-1) between linear
// values (what the film and EXR/PFM hold) and sRGB-encoded values (what PNG holds), plus the
// 8-bit quantisation used for PNG. No tone curve beyond an optional exposure multiplier: values
// above 1 clip, so a bright render is best inspected in EXR.
#pragma once

#include <cstdint>

#include "pathspace/math/scalar.h"

namespace pathspace {

// Linear -> sRGB-encoded. Linear segment below 0.0031308, power 1/2.4 above. Negative inputs stay
// on the linear segment (negative out); NaN propagates.
PS_INLINE float srgb_from_linear(float v) {
  return v <= 0.0031308f ? 12.92f * v : 1.055f * powf(v, 1.f / 2.4f) - 0.055f;
}

// sRGB-encoded -> linear, the inverse of srgb_from_linear.
PS_INLINE float linear_from_srgb(float s) {
  return s <= 0.04045f ? s * (1.f / 12.92f) : powf((s + 0.055f) * (1.f / 1.055f), 2.4f);
}

// Linear value (times exposure) -> 8-bit sRGB code, rounded to nearest. Clamped to [0, 255]:
// negatives and -Inf give 0, values >= 1 and +Inf give 255, NaN gives 0 (a PNG has no NaN).
PS_INLINE uint8_t to_srgb8(float linear, float exposure = 1.f) {
  const float v = linear * exposure;
  if (!(v > 0.f)) return 0;  // also catches NaN
  if (v >= 1.f) return 255;
  return uint8_t(srgb_from_linear(v) * 255.f + 0.5f);
}

}  // namespace pathspace
