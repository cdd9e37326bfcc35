// Options of the hashed path space filter (Binder, Fricke, Keller 2021) and their defaults.
#pragma once

#include "pathspace/filters/caustic_settings.h"
#include "pathspace/filters/hashed/temporal_settings.h"
#include "pathspace/filters/hashed/voxel_key.h"

namespace pathspace {

struct HashedFilterSettings {
  VoxelKeySettings key;         // voxel size, jitter, normal / direction / layer in the key
  float table_factor = 1.f;     // cells = next_pow2(table_factor * pixels) (sec. 4: ~ one per pixel)
  int max_probes = 16;          // bounded linear probing (sec. 3.2.2); <= 16 stays in one cache line (2019 paper, sec. 3.1)
  int min_count = 4;            // voxels with fewer vertices count as low-count (sec. 3.3)
  // Robust averages: a vertex adds its contribution to its voxel with the luminance clamped to this
  // (0: no clamp; docs/hashed-filter.md, "Robust averages").
  float max_luminance = 0.f;
  bool neighbour_search = false;  // sec. 3.3.1: add the 26 neighbouring voxels of a low-count voxel
  bool multi_level = false;       // sec. 3.3.2: also accumulate one level coarser, use it when low-count
  // Sec. 3.1.3: also accumulate one level coarser, and give each vertex the fine voxel or the coarse
  // one, whichever has the lower estimated squared error (adaptive resolution, prefer_fine_voxel).
  bool adaptive = false;
  int aa_paths = 0;                // extra query-only camera paths per pixel and pass (2014 paper, sec. 3)
  CausticSettings caustics;        // photon-mapped caustics beside the filter (2014 paper, sec. 2.3)
  bool local_combining = true;    // combine consecutive vertices of one voxel before the atomics
  // Find the cells of a step (for the level transfer, the per-cell blend and the next step's clear)
  // among all vertices instead of those that reached the table; the reference tests hold the
  // default to (it clears the whole table every step).
  bool step_cells_from_all_vertices = false;
  bool debug_images = false;      // keep per-vertex keys, probe and voxel counts for aov() (--aov)
  TemporalSettings temporal;      // sec. 3.4: the table kept across passes and frames
};

}  // namespace pathspace
