// Light tracing parameters and their defaults (integrators/lt/lt_kernel.h). The image-plane kernel
// of the camera projection (PCLT paper sec. 5.2) is the film's pixel filter (the camera's).
#pragma once

#include <cstdint>

namespace pathspace {

struct LtSettings {
  int max_segments = -1;         // path length limit in segments, camera connection included; -1: the scene's
  uint64_t light_paths = 0;      // light paths per pass; 0: one per pixel (SmallVCM)
  bool skip_emitter = false;     // do not splat the emitter itself (path length 1), as SmallVCM's LT
  int roulette_start = 3;        // Russian roulette from this many segments on; < 0 disables it
  double splat_scale = 0.0;      // fixed-point units per unit pixel value; 0: SplatFilm::kDefaultScale
};

}  // namespace pathspace
