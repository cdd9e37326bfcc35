// Path tracing parameters and their defaults.
#pragma once

#include "pathspace/filters/vertex_selection.h"
#include "pathspace/sampling/mis.h"

namespace pathspace {

struct PtSettings {
  int max_segments = -1;            // path length limit in segments (camera ray = 1); -1: the scene's
  bool nee = true;                  // next event estimation (light sampling)
  bool bsdf_sampling = true;        // count emission found by BSDF-sampled rays (after non-delta bounces)
  MisHeuristic mis = MisHeuristic::power;
  // In homogeneous scattering media: a light sample at an equiangular distance along each of the
  // path's first `equiangular_segments` segments (the camera ray is 1; 0: none), combined by MIS
  // with the distance-sampled one (media/equiangular.h, pt_kernel.h).
  int equiangular_segments = 64;
  int roulette_start = 3;           // Russian roulette from this many segments on; < 0 disables it
  bool texture_footprint = false;   // camera hits: textures averaged over the pixel (scene/texture_footprint.h)
  VertexSelection selection;        // where the path is split for path space filtering
};

}  // namespace pathspace
