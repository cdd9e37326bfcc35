// Display encoding: the exact piecewise sRGB transfer function (IEC 61966-2-1) between linear
// values (what the film and EXR/PFM hold) and sRGB-encoded values (what PNG holds), plus the
// 8-bit quantisation used for PNG. No tone curve beyond an optional exposure multiplier: values
// above 1 clip, so a bright render is best inspected in EXR.
#pragma once

#include <cstdint>

#include "pathspace/math/scalar.h"
#include "pathspace/math/srgb.h"  // srgb_from_linear, linear_from_srgb

namespace pathspace {

// Linear value (times exposure) -> 8-bit sRGB code, rounded to nearest. Clamped to [0, 255]:
// negatives and -Inf give 0, values >= 1 and +Inf give 255, NaN gives 0 (a PNG has no NaN).
PS_INLINE uint8_t to_srgb8(float linear, float exposure = 1.f) {
  const float v = linear * exposure;
  if (!(v > 0.f)) return 0;  // also catches NaN
  if (v >= 1.f) return 255;
  return uint8_t(srgb_from_linear(v) * 255.f + 0.5f);
}

}  // namespace pathspace
