// The hash table measurements of the hashed filter paper's short version (Binder, Fricke, Keller
// 2019; docs/papers-to-code.md): fig. 7, hash collisions (extra probes per insertion) and occupancy
// against the table size for several voxel sizes, local combining off so that every vertex probes
// the table; fig. 8, filter time (clear + accumulate + lookup, median over passes) against the voxel
// size. The one implementation behind `pathspace study psf` (its plots) and bench/studies/psf_figures
// (CSV files); both measure the filter on fixed vertex sets (vertex_sets.h) without rendering.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "pathspace/study/table.h"
#include "studies/psf2021/vertex_sets.h"

namespace pathspace::study {

struct HashTableSweep {
  std::vector<float> fig7_scales = {1.f, 2.f, 4.f, 8.f};  // voxel edge s in projected pixels
  std::vector<float> fig7_cells_per_pixel = {0.0625f, 0.125f, 0.25f, 0.5f, 1.f, 2.f, 4.f, 8.f};
  std::vector<float> fig8_scales = {0.5f, 1.f, 2.f, 4.f, 8.f, 16.f, 32.f};
  int fig8_passes = 5;  // timed passes after one warm-up; the median is reported
  int fig8_threads = 2;
  // One line per measurement (e.g. to stderr); empty: silent.
  std::function<void(const std::string&)> progress;
};

// Empty tables with the columns of psf_fig7.csv and psf_fig8.csv.
Table hash_collision_table();
Table filter_time_table();

// Appends one row per (scale, table size): vertex_set, psf_scale, cells_per_pixel, cells, occupancy,
// mean_probes, extra_probes, max_probes, fallbacks, expected_fingerprint_collisions.
void measure_hash_collisions(const VertexSet& set, const char* name, const HashTableSweep& sweep, Table* table);
// Appends one row per (scale, local combining on/off): vertex_set, threads, psf_scale, local_combining,
// accumulate_ms, lookup_ms, total_ms, occupancy, vertices.
void measure_filter_time(const VertexSet& set, const char* name, const HashTableSweep& sweep, Table* table);

}  // namespace pathspace::study
