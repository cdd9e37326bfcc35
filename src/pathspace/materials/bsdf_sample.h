// Result of sampling a BSDF. weight = f |cos theta_i| / pdf (docs/conventions.md); for delta
// lobes pdf is the discrete probability of the chosen lobe and `delta` is set.
#pragma once

#include <cstdint>

#include "pathspace/math/rgb.h"
#include "pathspace/math/vec3.h"

namespace pathspace {

enum LobeFlags : uint8_t {
  kLobeDiffuse = 1,
  kLobeGlossy = 2,
  kLobeSpecular = 4,  // a Dirac delta lobe
  kLobeReflection = 8,
  kLobeTransmission = 16,
};

struct BsdfSample {
  Vec3 wi;          // local frame
  Rgb weight;       // f |cos| / pdf, or the delta lobe's weight
  float pdf_w = 0;  // solid-angle pdf (non-delta) or discrete lobe probability (delta)
  uint8_t lobe = 0;
  bool delta = false;
  float eta = 1.f;  // relative IOR crossed (eta_wi_side / eta_wo_side) when transmitting, else 1
};

// Cosines below this are treated as grazing/zero (docs/scenes.md §6).
inline constexpr float kMinCosine = 1e-6f;

}  // namespace pathspace
