// The exact piecewise sRGB transfer function (IEC 61966-2-1) between linear and sRGB-encoded
// values: film/tonemap.h encodes images with it, scene/texture_bytes.cpp builds the 8-bit decoding
// table with it.
#pragma once

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

}  // namespace pathspace
