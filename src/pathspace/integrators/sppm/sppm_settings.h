// Stochastic progressive photon mapping parameters and their defaults (Hachisuka & Jensen 2009 with
// the Knaus & Zwicker 2011 global radius update, PCLT paper eq. 1).
#pragma once

#include <cstdint>

namespace pathspace {

struct SppmSettings {
  // Photons traced per iteration; 0: one per pixel (SmallVCM's choice, docs/scenes.md §6).
  uint64_t photons = 0;
  // Knaus-Zwicker alpha in r_{i+1} = r_i sqrt((i + alpha) / (i + 1)); smaller shrinks faster.
  float alpha = 2.f / 3.f;
  // Radius of the first iteration in scene units; <= 0: radius_fraction * bounding-sphere radius.
  float initial_radius = 0.f;
  // 1% of the bounding radius: ~4 pixel footprints in the 512^2 Cornell box, enough photons per
  // visible point (~10 per iteration) that early iterations are not dominated by noise.
  float radius_fraction = 0.01f;
  int max_segments = -1;     // path length limit (camera ray = segment 1); -1: the scene's
  int roulette_start = 3;    // Russian roulette for eye and photon paths from this many segments on
  // Eye paths continue through purely glossy vertices whose roughness (bsdf_layers.h scale:
  // Lambert 1, Phong 90 ~0.15) is below this, instead of storing a visible point there (a glossy
  // chain is then resolved by BSDF sampling, and emitters it reaches count directly).
  // 0: a visible point at the first vertex with any non-delta lobe.
  float glossy_roughness = 0.f;
};

}  // namespace pathspace
