// The GPU hashed filter's statistics (Statistics, which the CLI and studies print), apart from the
// filter itself so that cuda_hashed_filter.cu needs nothing of fmt or TBB. Compiled in every build:
// the report of the plain stats struct always, the method only where CUDA is built.
#include "pathspace/gpu/cuda_hashed_filter_stats.h"

#include <algorithm>

#include "pathspace/filters/temporal_statistics.h"
#include "pathspace/stats/statistics.h"

#if PATHSPACE_HAS_CUDA
#include "pathspace/gpu/cuda_hashed_filter.h"
#endif

namespace pathspace::gpu {

void report_statistics(const CudaHashedFilterStats& s, Statistics& out) {
  const double passes = double(std::max<uint64_t>(1, s.passes));
  const double vertices = double(std::max<uint64_t>(1, s.vertices));
  out.counter("cuda_hashed.passes", s.passes);
  out.value("cuda_hashed.vertices_per_pass", double(s.vertices) / passes);
  out.counter("cuda_hashed.table_cells", s.cells);
  out.bytes("cuda_hashed.table_bytes", s.table_bytes, "both levels with --psf-multi-level");
  out.ratio("cuda_hashed.occupancy", double(s.occupied_cells_last) / double(std::max<uint64_t>(1, s.cells)), "last pass");
  out.ratio("cuda_hashed.warp_aggregated", s.vertices ? 1.0 - double(s.insertions) / vertices : 0.0,
            "vertices added by their warp group's leader, not by an insertion of their own");
  out.value("cuda_hashed.mean_probes", s.mean_probes(), "cells inspected per insertion");
  out.counter("cuda_hashed.max_probes", s.probes_max);
  out.counter("cuda_hashed.probe_limit_fallbacks", s.probe_failures, "vertices that kept their own contribution");
  out.counter("cuda_hashed.not_accumulated", s.not_accumulated, "NaN, Inf, negative or huge contributions");
  out.counter("cuda_hashed.overflow_settled_passes", s.settled_passes, "passes whose full probe windows were settled by fingerprint");
  out.counter("cuda_hashed.low_count_vertices", s.low_count);
  out.counter("cuda_hashed.neighbour_lookups", s.neighbour_lookups);
  out.counter("cuda_hashed.coarse_level_used", s.multi_level_used);
  out.seconds("cuda_hashed.clear_s_per_pass", s.clear_ms * 1e-3 / passes, "cudaEvents");
  out.seconds("cuda_hashed.accumulate_s_per_pass", s.accumulate_ms * 1e-3 / passes, "keys, accumulation and settling");
  out.seconds("cuda_hashed.settle_s_per_pass", s.settle_ms * 1e-3 / passes);
  out.seconds("cuda_hashed.lookup_s_per_pass", s.lookup_ms * 1e-3 / passes);
  out.value("cuda_hashed.accumulate_ns_per_vertex", s.vertices ? s.accumulate_ms * 1e6 / vertices : 0.0);
  out.value("cuda_hashed.lookup_ns_per_vertex", s.vertices ? s.lookup_ms * 1e6 / vertices : 0.0);
  if (!s.temporal) return;
  report_temporal_statistics("cuda_hashed.",
                             {.steps = s.steps, .evicted = s.evicted, .evicted_last = s.evicted_last, .blended = s.blended,
                              .from_finer = s.from_finer, .from_coarser = s.from_coarser, .alpha_sum = s.alpha_sum,
                              .mean_alpha_last = s.mean_alpha_last, .temporal_ms = s.temporal_ms},
                             "level transfer, folding, priorities and eviction (cudaEvents)", out);
  out.counter("cuda_hashed.temporal.folded_last", s.folded_last, "cells used in the last step");
}

#if PATHSPACE_HAS_CUDA
void CudaHashedFilter::statistics(Statistics& out) const { report_statistics(stats_, out); }
#endif

}  // namespace pathspace::gpu
