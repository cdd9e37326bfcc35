#include "pathspace/filters/hashed/hashed_pass.h"

#include <algorithm>

#include "pathspace/filters/hashed/hashed_filter_keys.h"
#include "pathspace/filters/hashed/voxel_hash_table_view.h"

namespace pathspace {

namespace {

void add_counts(const HashedPassCounts& c, HashedFilterStats* s) {
  s->passes += 1;
  s->vertices += c.vertices;
  s->not_accumulated += c.not_accumulated;
  s->insertions += c.insertions;
  s->probes_total += c.probes;
  s->probes_max = std::max(s->probes_max, c.probes_max);
  s->probe_failures_last = c.failures;
  s->probe_failures += c.failures;
  s->low_count += c.low_count;
  s->neighbour_lookups += c.neighbour_lookups;
  s->multi_level_used += c.multi_level_used;
  s->occupied_cells_last = c.occupied_cells;
  s->expected_fingerprint_collisions_last = c.expected_fingerprint_collisions;
}

void add_temporal_counts(const HashedPassCounts& c, HashedFilterStats* s) {
  s->steps += 1;
  s->blended += c.blended;
  const double alpha = double(c.alpha_fixed) / 4294967296.0;
  s->alpha_sum += alpha;
  s->mean_alpha_last = c.blended ? alpha / double(c.blended) : 0.0;
  s->from_finer += c.from_finer;
  s->from_coarser += c.from_coarser;
  s->folded_last = c.folded;
  s->evicted += c.evicted;
  s->evicted_last = c.evicted;
}

}  // namespace

void run_hashed_pass(HashedPassSteps& steps, const HashedFilterSettings& settings, uint64_t seed, uint32_t pass,
                     HashedFilterStats* stats) {
  const uint64_t pass_hash = pass_jitter_hash(seed, pass);
  const bool temporal = settings.temporal.enabled();
  const uint32_t step = uint32_t(stats->steps);  // the histories' clock (sec. 3.4.3)

  steps.mark(PassMark::begin);
  steps.clear();
  steps.mark(PassMark::cleared);
  steps.accumulate(pass_hash);
  steps.mark(PassMark::accumulated);
  // Settled only where a probe window is one cache line (the default limit): then the outcome does
  // not depend on which thread came first (docs/hashed-filter.md, "Determinism").
  const uint64_t failures = steps.probe_failures();
  const bool settle = failures > 0 && settings.max_probes <= kFingerprintsPerLine;
  if (settle && steps.settle_overflows(pass_hash, failures)) ++stats->settled_passes;
  steps.mark(PassMark::settled);
  steps.list_step_cells();
  steps.mark(PassMark::listed);
  if (temporal && settings.temporal.level_transfer) steps.transfer_levels(pass_hash, step);
  if (temporal && settings.temporal.mode == TemporalMode::hybrid && pass == 0) steps.exchange_probes(seed, pass);
  steps.mark(PassMark::transferred);
  steps.lookup(pass_hash);
  steps.mark(PassMark::looked_up);
  if (temporal) steps.end_step(step + 1);
  steps.mark(PassMark::end);

  const HashedPassCounts counts = steps.finish();
  add_counts(counts, stats);
  if (temporal) add_temporal_counts(counts, stats);
  const auto ms = [&](PassMark from, PassMark to) { return steps.milliseconds(from, to); };
  stats->clear_ms_last = ms(PassMark::begin, PassMark::cleared);
  stats->settle_ms_last = settle ? ms(PassMark::accumulated, PassMark::settled) : 0.0;
  // Without settling, the interval up to `settled` holds only the device's wait for the failures.
  stats->accumulate_ms_last =
      ms(PassMark::cleared, PassMark::accumulated) + stats->settle_ms_last + ms(PassMark::settled, PassMark::listed);
  stats->lookup_ms_last = ms(PassMark::transferred, PassMark::looked_up);
  stats->clear_ms += stats->clear_ms_last;
  stats->accumulate_ms += stats->accumulate_ms_last;
  stats->settle_ms += stats->settle_ms_last;
  stats->lookup_ms += stats->lookup_ms_last;
  if (!temporal) return;
  stats->temporal_ms_last = ms(PassMark::listed, PassMark::transferred) + ms(PassMark::looked_up, PassMark::end);
  stats->temporal_ms += stats->temporal_ms_last;
}

}  // namespace pathspace
