// Pixel cache light tracing parameters and their defaults (PCLT paper, Hachisuka-style two passes:
// eye pass into the pixel cache, sec. 3; light pass gathering from the cache, sec. 3, and projecting to the camera, sec. 5).
// The radius follows Knaus & Zwicker (PCLT eq. 1) exactly as SPPM does (sppm_settings.h), so the
// two gather the same expectation for the same radius schedule (tested).
#pragma once

#include <cstdint>

namespace pathspace {

// How a projected light vertex is tested for visibility from the camera (sec. 5.3).
enum class PcltVisibility : uint8_t {
  shadow_ray,  // an occlusion ray: unbiased (default)
  z_buffer,    // depth of this iteration's jittered first hit in the pixel, plus epsilon * depth
  plane,       // half-space test against that first hit's plane, tolerance epsilon * view depth
};

// The search structure of the pixel cache (sec. 4; fig. 8).
enum class PcltHashMap : uint8_t { chained, stochastic };

struct PcltSettings {
  int max_segments = -1;        // path length limit (camera ray = segment 1); -1: the scene's
  uint64_t light_paths = 0;     // light paths per iteration; 0: one per pixel
  // Knaus-Zwicker alpha in r_{i+1} = r_i sqrt((i + alpha) / (i + 1)); the paper recommends [1/3, 2/3].
  float alpha = 2.f / 3.f;
  float initial_radius = 0.f;   // scene units; <= 0: radius_fraction * bounding-sphere radius
  float radius_fraction = 0.01f;  // as SPPM (sppm_settings.h: ~4 pixel footprints at 512^2)
  int roulette_start = 3;       // Russian roulette for eye and light paths from this many segments on
  PcltVisibility visibility = PcltVisibility::shadow_ray;
  float epsilon = 5e-4f;        // z-buffer / plane tolerance relative to the view depth (sec. 5.3)
  // Emission reached through >= 1 specular/glossy eye bounce (ES+L). The paper leaves these paths
  // to light tracing, which practically never finds them through a delta bounce; adding them from
  // the eye path (like SPPM's direct term) makes PCLT converge to the full image. false = the paper.
  bool specular_emission = true;
  PcltHashMap hash_map = PcltHashMap::chained;
  uint32_t stochastic_slots = 0;  // stochastic map table size (power of two); 0: bit_ceil(capacity)
  uint64_t cache_capacity = 0;    // records kept per iteration; 0: the pixel count (never full)
  // When more pixels qualify than the capacity holds: keep a uniform random subset and reweight
  // by candidates / capacity (unbiased, sec. 6 "store stochastically once the buffer is full");
  // false keeps the first ones in pixel order and drops the rest (reported).
  bool stochastic_store = false;
  double splat_scale = 0.0;       // fixed-point units per unit pixel value; 0: SplatFilm default
};

}  // namespace pathspace
