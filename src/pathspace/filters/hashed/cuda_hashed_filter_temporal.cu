// The GPU hashed filter's table across frames (Binder et al. 2021, sec. 3.4; cuda_hashed_filter.h):
// the level transfer of new cells (3.4.2) and the folding, priorities and eviction after a step
// (3.4.3) as kernels over filters/hashed/temporal_steps.h, and the keys and histories of a checkpoint. The
// blend of 3.4.1 is in the lookup kernel (cuda_hashed_filter.cu).
#include "pathspace/filters/hashed/cuda_hashed_filter.h"

#include <vector>

#include "pathspace/filters/hashed/cuda_filter_kernels.h"

namespace pathspace::gpu {

namespace {

using namespace filter_kernels;

// Sec. 3.4.2, phase 1 (HashedFilter::transfer_levels): the first vertex of each cell new to the
// table (no history) computes its transfer from the histories as they were; every vertex of a cell
// has the same key, so which one does it does not change the result.
__global__ void transfer_claim_kernel(HashedStepSettings s, TemporalSettings temporal, VertexBufferView b, uint64_t pass_hash,
                                      VoxelHashTableView table, const int32_t* slots, const VoxelHistory* history,
                                      uint32_t step, uint32_t* claimed, VoxelHistory* transferred,
                                      unsigned long long* counters) {
  __shared__ unsigned block[kCounters];
  block_counters_init(block);
  const size_t i = thread_index();
  LevelTransfer kind = LevelTransfer::none;
  if (valid_slot(b, i)) {
    const int32_t cell = slots[i];
    if (cell >= 0 && !(history[cell].weight > 0.f) && atomicCAS(&claimed[cell], 0u, 1u) == 0u) {
      VoxelHistory out;
      kind = level_transfer(temporal, table, history, s.key.normal, key_for_pass(s.key, b, i, pass_hash), step, &out);
      if (kind != LevelTransfer::none) {
        transferred[cell] = out;
        claimed[cell] = 2u;
      }
    }
  }
  if (kind == LevelTransfer::from_finer) atomicAdd(&block[kFromFiner], 1u);
  if (kind == LevelTransfer::from_coarser) atomicAdd(&block[kFromCoarser], 1u);
  block_counters_flush(block, counters);
}

// Phase 2: the transfers take effect; the claims are cleared for the next step.
__global__ void transfer_apply_kernel(uint64_t cells, uint32_t* claimed, const VoxelHistory* transferred, VoxelHistory* history) {
  const size_t c = thread_index();
  if (c >= cells) return;
  if (claimed[c] == 2u) history[c] = transferred[c];
  claimed[c] = 0u;
}

// Without hybrid probes a cell's change is its history's (TemporalHistory::change).
struct HistoryChange {
  const VoxelHistory* history;
  __device__ float operator()(uint64_t c) const { return history[c].change; }
};

// Sec. 3.4.3 after the step's lookups: one thread per probe window folds, prioritises and evicts
// (TemporalHistory::end_step).
__global__ void end_step_kernel(TemporalSettings temporal, uint32_t keep, VoxelHashTableView table, VoxelHistory* history,
                                uint64_t windows, uint32_t step, unsigned long long* counters) {
  __shared__ unsigned block[kCounters];
  block_counters_init(block);
  const size_t w = thread_index();
  if (w < windows) {
    const TemporalWindowCounts n =
        fold_and_evict_window(temporal, keep, table, history, uint64_t(w) * kFingerprintsPerLine, step, HistoryChange{history});
    if (n.folded) atomicAdd(&block[kFolded], n.folded);
    if (n.evicted) atomicAdd(&block[kEvicted], n.evicted);
  }
  block_counters_flush(block, counters);
}

}  // namespace

// Sec. 3.4.2: new cells take the history of their finer or coarser voxels (two kernels: every claim
// reads the histories as they were before any transfer is written).
void CudaHashedFilter::transfer_levels(const VertexBufferView& b, uint64_t pass_hash, uint32_t step, cudaStream_t stream) {
  transfer_claim_kernel<<<blocks_for(b.slots()), kBlock, 0, stream>>>(steps_, settings_.temporal, b, pass_hash, table(), slots_.data(),
                                                                       history_.data(), step,
                                                                       transfer_claimed_.data(), transferred_.data(), counters_.data());
  PS_CUDA_CHECK_LAUNCH("transfer_claim_kernel");
  transfer_apply_kernel<<<blocks_for(cells_), kBlock, 0, stream>>>(cells_, transfer_claimed_.data(), transferred_.data(), history_.data());
  PS_CUDA_CHECK_LAUNCH("transfer_apply_kernel");
}

// Sec. 3.4.3: folding, priorities and eviction, one probe window per thread; the step counts from 1.
void CudaHashedFilter::end_step(uint32_t step, cudaStream_t stream) {
  const uint64_t windows = cells_ / kFingerprintsPerLine;
  end_step_kernel<<<blocks_for(windows), kBlock, 0, stream>>>(settings_.temporal, temporal_window_keep(settings_.temporal), table(),
                                                              history_.data(), windows, step, counters_.data());
  PS_CUDA_CHECK_LAUNCH("end_step_kernel");
}

void CudaHashedFilter::save_state(StateWriter& out) const {
  out.put("hashed.stats", stats_);
  if (!settings_.temporal.enabled()) return;
  out.put_vector("hashed.temporal.fingerprints", fingerprints_.download());
  out.put_vector("hashed.temporal.history", history_.download());
}

void CudaHashedFilter::load_state(StateReader& in) {
  in.get("hashed.stats", &stats_);
  if (!settings_.temporal.enabled()) return;
  std::vector<uint32_t> fingerprints;
  std::vector<VoxelHistory> history;
  in.get_vector("hashed.temporal.fingerprints", &fingerprints, size_t(cells_));
  in.get_vector("hashed.temporal.history", &history, size_t(cells_));
  fingerprints_.upload(fingerprints);
  history_.upload(history);
}

}  // namespace pathspace::gpu
