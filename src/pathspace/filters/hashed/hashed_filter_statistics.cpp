// The hashed filter's statistics (Statistics, which the CLI, Python and the studies print), for both
// devices from the one HashedFilterStats. Apart from the filters so that the CUDA driver needs
// nothing of fmt or TBB; compiled in every build.
#include <algorithm>

#include "pathspace/filters/hashed/hashed_filter_stats.h"
#include "pathspace/stats/statistics.h"

namespace pathspace {

void report_statistics(const HashedFilterStats& s, const HashedStatsScope& scope, Statistics& out) {
  const bool gpu = s.device == FilterDevice::cuda;
  const double passes = double(std::max<uint64_t>(1, s.passes));
  const double vertices = double(std::max<uint64_t>(1, s.vertices));
  const char* const clock = gpu ? "cudaEvents" : "steady clock";
  out.text("hashed.device", gpu ? "cuda" : "cpu", "where the filter ran (--device)");
  out.counter("hashed.passes", s.passes);
  out.value("hashed.vertices_per_pass", double(s.vertices) / passes);
  out.counter("hashed.table_cells", s.cells);
  out.bytes("hashed.table_bytes", s.table_bytes, "both levels with --psf-multi-level");
  out.ratio("hashed.occupancy", double(s.occupied_cells_last) / double(std::max<uint64_t>(1, s.cells)), "last pass");
  out.ratio("hashed.combined_locally", s.vertices ? 1.0 - double(s.insertions) / vertices : 0.0,
            gpu ? "vertices added by their warp group's leader, not by an insertion of their own"
                : "vertices added in the per-thread cache, not by a table atomic");
  out.value("hashed.mean_probes", s.mean_probes(), "cells inspected per insertion");
  out.counter("hashed.max_probes", s.probes_max);
  out.counter("hashed.probe_limit_fallbacks", s.probe_failures, "vertices that kept their own contribution");
  out.counter("hashed.probe_limit_fallbacks_last", s.probe_failures_last, "last pass");
  out.counter("hashed.not_accumulated", s.not_accumulated, "NaN, Inf, negative or huge contributions");
  out.counter("hashed.overflow_settled_passes", s.settled_passes, "passes whose full probe windows were settled by fingerprint");
  if (!gpu) out.value("hashed.expected_fingerprint_collisions", s.expected_fingerprint_collisions_last, "last pass");
  out.counter("hashed.low_count_vertices", s.low_count);
  out.counter("hashed.neighbour_lookups", s.neighbour_lookups);
  out.counter("hashed.coarse_level_used", s.multi_level_used, "vertices that took the coarser voxel (--psf-multi-level, --psf-adaptive)");
  out.seconds("hashed.clear_s_per_pass", s.clear_ms * 1e-3 / passes, clock);
  out.seconds("hashed.accumulate_s_per_pass", s.accumulate_ms * 1e-3 / passes, "keys, accumulation and settling");
  out.seconds("hashed.settle_s_per_pass", s.settle_ms * 1e-3 / passes);
  out.seconds("hashed.lookup_s_per_pass", s.lookup_ms * 1e-3 / passes);
  out.value("hashed.accumulate_ns_per_vertex", s.vertices ? s.accumulate_ms * 1e6 / vertices : 0.0);
  out.value("hashed.lookup_ns_per_vertex", s.vertices ? s.lookup_ms * 1e6 / vertices : 0.0);
  if (scope.query_paths) {
    out.counter("hashed.query_records", s.query_records, "vertices of the query-only anti-aliasing paths (--psf-aa-paths)");
    out.counter("hashed.query_found", s.query_found, "of those, in a voxel with an estimate (the others' paths are left out)");
  }
  if (scope.adaptive)
    out.counter("hashed.adaptive.refined_voxels", scope.refined_voxels, "fine voxels whose vertices take the fine average in the next pass (sec. 3.1.3)");
  if (!s.temporal) return;
  out.counter("hashed.temporal.steps", s.steps, "passes whose table carried to the next (sec. 3.4)");
  out.counter("hashed.temporal.evicted", s.evicted, "cells evicted between steps (sec. 3.4.3)");
  out.counter("hashed.temporal.evicted_last", s.evicted_last, "last step");
  out.counter("hashed.temporal.folded_last", s.folded_last, "cells used in the last step");
  out.value("hashed.temporal.mean_alpha", s.blended ? s.alpha_sum / double(s.blended) : 0.0,
            "weight of the history in the vertices' estimates (sec. 3.4.1)");
  out.value("hashed.temporal.mean_alpha_last", s.mean_alpha_last, "last step");
  out.seconds("hashed.temporal.s_per_step", s.steps ? s.temporal_ms * 1e-3 / double(s.steps) : 0.0,
              "level transfer, folding, priorities and eviction");
  out.counter("hashed.temporal.from_finer", s.from_finer, "new cells that took their finer voxels' sums (sec. 3.4.2)");
  out.counter("hashed.temporal.from_coarser", s.from_coarser, "new cells that took their coarser voxel's average (sec. 3.4.2)");
  if (!scope.hybrid) return;
  out.counter("hashed.temporal.probes", s.probes, "previous-frame paths traced again (hybrid)");
  out.counter("hashed.temporal.probes_in_table", s.probes_found, "of those, in a voxel of the table");
  out.value("hashed.temporal.mean_change", s.probes_found ? s.change_sum / double(s.probes_found) : 0.0,
            "relative change of a re-traced path's contribution");
}

}  // namespace pathspace
