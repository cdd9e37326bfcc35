// Bidirectional path tracing parameters and their defaults (integrators/bpt/bpt_kernel.h; Veach 1997
// ch. 10, MIS as in Georgiev et al. 2012, "Light transport simulation with vertex connection and
// merging", tech. report sec. on BPT). One light subpath per pixel and pass (SmallVCM).
#pragma once

#include <cstdint>

#include "pathspace/sampling/mis.h"

namespace pathspace {

// The longest path BPT accepts: light vertices live in a fixed-size array inside the kernel
// (device-safe, no allocation), one per light-subpath segment.
inline constexpr int kBptMaxSegments = 32;

struct BptSettings {
  int max_segments = -1;                 // path length limit in segments (camera ray = 1); -1: the scene's
  MisHeuristic mis = MisHeuristic::power;
  int roulette_start = 3;                // Russian roulette from this many segments on (either subpath); < 0: off
  double splat_scale = 0.0;              // fixed-point units per unit pixel value for t = 1; 0: SplatFilm default
  int strategy_images = 0;               // > 0: keep one image per (s, t) for path lengths up to this many segments
};

// Strategies (s, t) of path length k = s + t - 1 segments are s = 0 .. k (t >= 1: a pinhole cannot
// be hit, so t = 0 does not exist); they are numbered by length, then s.
PS_HD inline constexpr int bpt_strategy_index(int s, int t) {
  const int k = s + t - 1;
  return (k - 1) * (k + 2) / 2 + s;
}
PS_HD inline constexpr int bpt_strategy_count(int max_length) { return max_length * (max_length + 3) / 2; }

}  // namespace pathspace
