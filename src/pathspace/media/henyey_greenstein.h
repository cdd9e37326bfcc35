// The Henyey-Greenstein phase function (Henyey and Greenstein 1941; pbrt-v4 sec. 11.3.1) of the
// angle between the incoming and the outgoing travel direction, and its exact sampling. Media
// (media/medium.h) and the layered BSDF's slab (materials/layered_bsdf.h) share it.
#pragma once

#include "pathspace/math/frame.h"
#include "pathspace/math/scalar.h"
#include "pathspace/sampling/warps.h"

namespace pathspace {

// Density over the sphere of outgoing travel directions; g in (-1, 1): > 0 forward scattering.
PS_INLINE float hg_phase(float cos_travel, float g) {
  const float denom = 1.f + g * g - 2.f * g * cos_travel;
  return kInvFourPi * (1.f - g * g) / (denom * safe_sqrt(denom));
}

// A new travel direction after scattering of a walk travelling along `w`; its density is
// hg_phase(dot(w, result), g), so the weight is 1 (exact sampling).
PS_INLINE Vec3 hg_sample(const Vec3& w, float g, Point2 u) {
  float cos_t;
  if (fabsf(g) < 1e-3f) {
    cos_t = 1.f - 2.f * u.x;
  } else {
    const float s = (1.f - g * g) / (1.f - g + 2.f * g * u.x);
    cos_t = clamp_to((1.f + g * g - s * s) / (2.f * g), -1.f, 1.f);
  }
  const float sin_t = safe_sqrt(1.f - cos_t * cos_t), phi = kTwoPi * u.y;
  return Frame(w).to_world(Vec3(sin_t * cosf(phi), sin_t * sinf(phi), cos_t));
}

}  // namespace pathspace
