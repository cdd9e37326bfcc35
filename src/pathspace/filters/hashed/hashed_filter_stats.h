// What a hashed filter did (Binder et al. 2021, sec. 3-4), on either device: HashedFilter (CPU) and
// CudaHashedFilter (GPU) fill the same struct, reported as "hashed.<what>" with "hashed.device"
// naming the device (hashed_filter_statistics.cpp). Plain data: the CUDA driver includes it, and
// checkpoints store it as bytes.
#pragma once

#include <cstddef>
#include <cstdint>

namespace pathspace {

class Statistics;

enum class FilterDevice : uint8_t { cpu, cuda };

struct HashedFilterStats {
  FilterDevice device = FilterDevice::cpu;
  bool temporal = false;  // --temporal: the table carries from step to step (sec. 3.4)
  uint64_t passes = 0, vertices = 0;
  uint64_t not_accumulated = 0;  // NaN/Inf/negative/huge contribution: kept its own contribution
  // Table insertions: CPU, vertices not combined in their thread's cache; GPU, one per warp group of
  // equal keys (sec. 4). The other vertices were combined before reaching the table.
  uint64_t insertions = 0;
  uint64_t probes_total = 0, probes_max = 0;             // cells inspected by those insertions
  uint64_t probe_failures = 0, probe_failures_last = 0;  // after settling: kept their own contribution
  uint64_t settled_passes = 0;  // passes whose full probe windows were settled by fingerprint
  uint64_t low_count = 0;       // vertices whose voxel had fewer than min_count vertices
  uint64_t neighbour_lookups = 0, multi_level_used = 0;
  uint64_t occupied_cells_last = 0, cells = 0;
  double expected_fingerprint_collisions_last = 0.0;  // measured on the CPU only (VoxelHashTable::occupancy)
  size_t table_bytes = 0;
  // Milliseconds (steady clock on the CPU, cudaEvents on the GPU), summed over passes, and the last
  // pass's; accumulate includes settling.
  double clear_ms = 0, accumulate_ms = 0, settle_ms = 0, lookup_ms = 0;
  double clear_ms_last = 0, accumulate_ms_last = 0, settle_ms_last = 0, lookup_ms_last = 0;
  // Sec. 3.4 (--temporal): summed over steps, and the last step's.
  uint64_t steps = 0, blended = 0, evicted = 0, evicted_last = 0, folded_last = 0;
  uint64_t from_finer = 0, from_coarser = 0;  // sec. 3.4.2: new cells that took another level's history
  double alpha_sum = 0.0, mean_alpha_last = 0.0;
  double temporal_ms = 0.0, temporal_ms_last = 0.0;  // level transfer, folding, priorities and eviction
  // --temporal hybrid: re-traced paths, those whose voxel was in the table, their relative changes.
  uint64_t probes = 0, probes_found = 0;
  double change_sum = 0.0;
  uint64_t query_records = 0, query_found = 0;  // --psf-aa-paths: queried vertices, and those with an estimate

  // Mean cells inspected per insertion (1 = found or claimed the home cell).
  double mean_probes() const { return insertions ? double(probes_total) / double(insertions) : 0.0; }
  // Zero statistics that keep what describes the filter: device, table size, and the step count,
  // which is the histories' clock (recency, sec. 3.4.3), not only a statistic.
  HashedFilterStats fresh() const {
    HashedFilterStats s;
    s.device = device;
    s.temporal = temporal;
    s.cells = cells;
    s.table_bytes = table_bytes;
    s.steps = steps;
    return s;
  }
};

// What the report includes beyond the struct: the features only some settings have.
struct HashedStatsScope {
  bool query_paths = false;  // --psf-aa-paths
  bool hybrid = false;       // --temporal hybrid
  bool adaptive = false;     // --psf-adaptive, with the voxels refined for the next pass
  uint64_t refined_voxels = 0;
};

// Fills `out` with "hashed.<what>" (and "hashed.temporal.<what>" with --temporal).
void report_statistics(const HashedFilterStats& s, const HashedStatsScope& scope, Statistics& out);

}  // namespace pathspace
