#include "pathspace/filters/temporal_statistics.h"

namespace pathspace {

void report_temporal_statistics(const std::string& prefix, const TemporalTotals& t, const char* timed, Statistics& out) {
  const std::string p = prefix + "temporal.";
  out.counter(p + "steps", t.steps, "passes whose table carried to the next (sec. 3.4)");
  out.counter(p + "evicted", t.evicted, "cells evicted between steps (sec. 3.4.3)");
  out.counter(p + "evicted_last", t.evicted_last, "last step");
  out.value(p + "mean_alpha", t.blended ? t.alpha_sum / double(t.blended) : 0.0,
            "weight of the history in the vertices' estimates (sec. 3.4.1)");
  out.value(p + "mean_alpha_last", t.mean_alpha_last, "last step");
  out.seconds(p + "s_per_step", t.steps ? t.temporal_ms * 1e-3 / double(t.steps) : 0.0, timed);
  out.counter(p + "from_finer", t.from_finer, "new cells that took their finer voxels' sums (sec. 3.4.2)");
  out.counter(p + "from_coarser", t.from_coarser, "new cells that took their coarser voxel's average (sec. 3.4.2)");
}

}  // namespace pathspace
