// --psf-aa-paths for the hashed filter: extra camera paths per pixel end at their first selected
// vertex and take its estimate from the table the pass left (Keller, Dahm, Binder 2014, sec. 3,
// fig. 7, which the 2021 filter inherits): a pixel then averages several primary hits, so edges and
// texture detail that one hit per pixel aliases converge, for the price of a primary ray and a
// lookup instead of a path. Queries add nothing to the table. A query vertex is keyed like a
// vertex of the pass (batched, voxel_key_blocks.h), with a jitter of its own per round of queries;
// it finds its voxel or not (not: its path is left out of the pixel, as the consistent filter's
// empty queries are).
#include <atomic>

#include "pathspace/filters/hashed/hashed_filter.h"
#include "pathspace/filters/hashed/voxel_key_blocks.h"
#include "pathspace/parallel/parallel_for.h"

namespace pathspace {

void HashedFilter::query(const VertexBuffer& queries, SlotValues* values, std::vector<uint8_t>* found) {
  const size_t slots = queries.paths() * size_t(queries.records_per_path());
  values->assign(slots, Rgb());
  found->assign(slots, 0);
  const VoxelHashTableView view = table_.view();
  const VoxelHashTableView coarse = coarse_table_ ? coarse_table_->view() : VoxelHashTableView{};
  const HashedStepSettings steps = step_settings(settings_);
  const uint64_t pass_hash = hash_combine(pass_hash_, ++query_round_);
  const VertexBufferView qv = queries.view();
  const TemporalHistory* history = history_.get();
  const VoxelKeyIsa isa = widest_voxel_key_isa();
  std::atomic<uint64_t> records{0}, hits{0};
  parallel_for(queries.paths(), kGrain, [&](size_t begin, size_t end) {
    LookupCounters ignored;  // the pass's own lookups keep the low-count statistics
    uint64_t local_records = 0, local_hits = 0;
    VoxelKeyBlocks blocks(settings_.key, qv, begin, end, pass_hash, isa);
    const VoxelKeyBatch& keys = blocks.batch();
    for (int n = blocks.next(); n > 0; n = blocks.next())
      for (int j = 0; j < n; ++j) {
        const size_t i = blocks.slot(j);
        ++local_records;
        const VoxelKey& key = keys.keys[j];
        const ProbeResult pr = view.find(keys.hashes[j]);
        if (pr.slot < 0) continue;
        const int32_t s = int32_t(pr.slot);
        const VoxelCell& cell = view.cells[s];
        Rgb average;
        // Sec. 3.4.1: after the pass a used cell's history holds its blend (end_step folded it);
        // a cell unused in this pass keeps the estimate of the step that used it last.
        if (history && history->at(uint64_t(s)).weight > 0.f) {
          const VoxelHistory& h = history->at(uint64_t(s));
          average = {h.mean[0], h.mean[1], h.mean[2]};
        } else if (cell.count > 0) {
          average = from_fixed_point(cell.sum, cell.count);
        } else {
          continue;
        }
        int32_t coarse_slot = kSlotProbeFailed;
        if (coarse_table_) coarse_slot = int32_t(coarse.find(hash_voxel_key(coarser_key(key), settings_.key.normal)).slot);
        (*values)[i] = level_estimate(s, coarse_slot, key, average, steps, &ignored);
        (*found)[i] = 1;
        ++local_hits;
      }
    records += local_records;
    hits += local_hits;
  });
  stats_.query_records += records;
  stats_.query_found += hits;
}

}  // namespace pathspace
