#include "pathspace/filters/hashed/cuda_hashed_filter.h"

#include <algorithm>
#include <map>
#include <string>
#include <vector>

#include "pathspace/filters/hashed/hashed_filter_limits.h"
#include "pathspace/filters/hashed/hashed_pass.h"
#include "pathspace/filters/hashed/overflow_settling.h"
#include "pathspace/filters/hashed/cuda_filter_kernels.h"

namespace pathspace::gpu {

namespace {

using namespace filter_kernels;

// Warp aggregation (sec. 4: neighbouring pixels' primary hits mostly share a voxel): the lanes of
// `mask` with the same hash form a group; its leader inserts once and adds the group's summed
// fixed-point values and count, the others take the leader's slot. Integer sums: the cell is the
// same as with one add per vertex.
static_assert(uint64_t(kMaxAccumulatedValue) * uint64_t(kFixedPointScale) <= (uint64_t(1) << 40),
              "aggregated_insert splits fixed-point values of at most 2^40 at bit 24");

struct AggregatedInsert {
  ProbeResult result;
  bool leader = false;
};

__device__ AggregatedInsert aggregated_insert(unsigned mask, const VoxelHashTableView& t, const VoxelHash& h,
                                              const uint64_t fixed[3]) {
  const unsigned group = __match_any_sync(mask, (unsigned long long)h.index) & __match_any_sync(mask, h.fingerprint);
  const int leader = __ffs(group) - 1;
  uint64_t sum[3] = {fixed[0], fixed[1], fixed[2]};
  // Each group sums its own lanes (groups run divergently, each with its own mask). REDUX adds 32-bit
  // values: a value (at most 2^40, to_fixed_point) is split at bit 24, so that neither part's sum
  // over 32 lanes can overflow (< 2^29 and < 2^21), and the sum is reassembled exactly.
  if (group != (1u << lane_id()))
    for (int c = 0; c < 3; ++c) {
      const unsigned low = __reduce_add_sync(group, unsigned(fixed[c] & 0xffffffu));
      const unsigned high = __reduce_add_sync(group, unsigned(fixed[c] >> 24));
      sum[c] = uint64_t(low) + (uint64_t(high) << 24);
    }
  AggregatedInsert out;
  out.leader = lane_id() == leader;
  if (out.leader) out.result = insert_and_add(t, h, sum, uint64_t(__popc(group)));
  out.result.slot = __shfl_sync(mask, (long long)out.result.slot, leader);
  return out;
}

// Keys and accumulation, one thread per record slot (sec. 3.1-3.2; 3.3.2 with multi-level).
__global__ void accumulate_kernel(HashedStepSettings s, VertexBufferView b, uint64_t pass_hash, VoxelHashTableView table,
                                  VoxelHashTableView coarse, int32_t* slots, int32_t* coarse_slots,
                                  unsigned long long* counters) {
  __shared__ unsigned block[kCounters];
  block_counters_init(block);
  const size_t i = thread_index();
  const bool valid = valid_slot(b, i);
  PreparedVertex v;
  if (valid) v = prepare_vertex(s, b, i, pass_hash);
  const bool accumulated = valid && v.accumulated;
  if (valid && !accumulated) slots[i] = kSlotNotAccumulated;
  const unsigned valid_mask = __ballot_sync(kFullWarp, valid);
  const unsigned mask = __ballot_sync(kFullWarp, accumulated);
  if (lane_id() == 0) {
    if (valid_mask) atomicAdd(&block[kVertices], unsigned(__popc(valid_mask)));
    if (valid_mask & ~mask) atomicAdd(&block[kNotAccumulated], unsigned(__popc(valid_mask & ~mask)));
  }
  if (accumulated) {
    if (s.multi_level) coarse_slots[i] = int32_t(aggregated_insert(mask, coarse, coarse_hash(s, v.key), v.fixed).result.slot);
    const AggregatedInsert a = aggregated_insert(mask, table, v.hash, v.fixed);
    slots[i] = int32_t(a.result.slot);
    warp_add(mask, &block[kInsertions], a.leader ? 1u : 0u);
    warp_add(mask, &block[kProbes], a.leader ? unsigned(a.result.probes) : 0u);
    warp_max(mask, &block[kProbesMax], a.leader ? unsigned(a.result.probes) : 0u);
    warp_add(mask, &block[kFailures], a.result.slot < 0 ? 1u : 0u);
  }
  block_counters_flush(block, counters);
}

// Sec. 3.3: each valid slot's filtered contribution; with a history (--temporal, which keeps one
// level without neighbours) the cell's average blended with it as HashedFilter::lookup does (3.4.1).
__global__ void lookup_kernel(HashedStepSettings s, VertexBufferView b, uint64_t pass_hash, VoxelHashTableView table,
                              VoxelHashTableView coarse, const int32_t* slots, const int32_t* coarse_slots,
                              TemporalSettings temporal, const VoxelHistory* history, Rgb* filtered,
                              unsigned long long* counters) {
  __shared__ unsigned block[kCounters];
  __shared__ unsigned long long block_alpha;
  if (threadIdx.x == 0) block_alpha = 0;
  block_counters_init(block);
  const size_t i = thread_index();
  const bool valid = valid_slot(b, i);
  const unsigned mask = __ballot_sync(kFullWarp, valid);
  unsigned long long alpha_fixed = 0;
  bool blended = false;
  if (valid) {
    LookupCounters c;
    const int32_t slot = slots[i];
    if (history && slot >= 0) {
      const VoxelCell& cell = table.cells[slot];
      float alpha = 0.f;
      Rgb average = temporal_blend(temporal, history[slot], cell, 0.f, &alpha);
      blended = true;
      alpha_fixed = (unsigned long long)(double(alpha) * 4294967296.0);
      if (cell.count < s.min_count) average = low_count_average(s, table, coarse, cell, average, VoxelKey{}, kSlotProbeFailed, &c);
      filtered[i] = average;
    } else {
      filtered[i] = lookup_vertex(s, b, i, pass_hash, table, coarse, slot, s.multi_level ? coarse_slots[i] : kSlotProbeFailed, &c);
    }
    warp_add(mask, &block[kLowCount], unsigned(c.low_count));
    warp_add(mask, &block[kNeighbourLookups], unsigned(c.neighbour_lookups));
    warp_add(mask, &block[kMultiLevelUsed], unsigned(c.multi_level_used));
    warp_add(mask, &block[kBlended], blended ? 1u : 0u);
  }
  if (history) {  // every thread of the warp takes part (invalid ones add 0)
    for (int offset = 16; offset > 0; offset >>= 1) alpha_fixed += __shfl_down_sync(kFullWarp, alpha_fixed, offset);
    if (lane_id() == 0 && alpha_fixed) atomicAdd(&block_alpha, alpha_fixed);
  }
  block_counters_flush(block, counters);  // begins with a barrier: block_alpha is complete after it
  if (threadIdx.x == 0 && block_alpha) atomicAdd(&counters[(blockIdx.x % kCopies) * kCounters + kAlphaSum], block_alpha);
}

__global__ void occupancy_kernel(const uint32_t* fingerprints, uint64_t cells, unsigned long long* counters) {
  __shared__ unsigned block[kCounters];
  block_counters_init(block);
  const size_t c = thread_index();
  const unsigned occupied = __ballot_sync(kFullWarp, c < cells && fingerprints[c] != kEmptyFingerprint);
  if (lane_id() == 0 && occupied) atomicAdd(&block[kOccupied], unsigned(__popc(occupied)));
  block_counters_flush(block, counters);
}

// Settling (hashed_filter_overflow.cpp): the failed vertices' windows and stored fingerprints.
struct FailedVertex {
  unsigned long long slot, window;
  uint32_t key;
};

__global__ void list_failed_kernel(HashedStepSettings s, VertexBufferView b, uint64_t pass_hash, VoxelHashTableView table,
                                   const int32_t* slots, FailedVertex* out, unsigned long long capacity,
                                   unsigned long long* counters) {
  const size_t i = thread_index();
  if (!valid_slot(b, i) || slots[i] != kSlotProbeFailed) return;
  const VoxelHash h = hash_voxel_key(key_for_pass(s.key, b, i, pass_hash), s.key.normal);
  const unsigned long long k = atomicAdd(&counters[kFailedListed], 1ull);
  if (k < capacity) out[k] = {i, (h.index & table.mask) / kFingerprintsPerLine, table.stored_fingerprint(h)};
}

__global__ void reassign_kernel(VoxelHashTableView table, const unsigned long long* cells, const uint32_t* keys, size_t n,
                                uint8_t* reassigned) {
  const size_t k = thread_index();
  if (k >= n) return;
  table.fingerprints[cells[k]] = keys[k];
  table.cells[cells[k]] = VoxelCell{};
  reassigned[cells[k]] = 1;
}

// The losers' vertices fall back to their own contributions ...
__global__ void drop_losers_kernel(VertexBufferView b, int32_t* slots, const uint8_t* reassigned, unsigned long long* counters) {
  const size_t i = thread_index();
  const bool lost = valid_slot(b, i) && slots[i] >= 0 && reassigned[slots[i]];
  if (lost) slots[i] = kSlotProbeFailed;
  const unsigned m = __ballot_sync(kFullWarp, lost);
  if (lane_id() == 0 && m) atomicAdd(&counters[kLost], (unsigned long long)__popc(m));
}

// ... and the winners' vertices fill their cells (keys sorted: binary search).
__global__ void add_winners_kernel(HashedStepSettings s, VertexBufferView b, VoxelHashTableView table, const FailedVertex* failed,
                                   size_t n, const uint32_t* keys, const unsigned long long* cells, size_t winners,
                                   int32_t* slots, unsigned long long* counters) {
  const size_t k = thread_index();
  if (k >= n) return;
  const FailedVertex f = failed[k];
  size_t lo = 0, hi = winners;
  while (lo < hi) {
    const size_t mid = (lo + hi) / 2;
    if (keys[mid] < f.key) lo = mid + 1; else hi = mid;
  }
  if (lo == winners || keys[lo] != f.key) return;
  uint64_t fixed[3];
  if (!accumulated_fixed_point(s, b.contribution[f.slot], fixed)) return;  // never the case for a failure
  add_to_cell(table, cells[lo], fixed, 1);
  slots[f.slot] = int32_t(cells[lo]);
  atomicAdd(&counters[kWon], 1ull);
}



}  // namespace

CudaHashedFilter::CudaHashedFilter(const HashedFilterSettings& settings, const PerspectiveCamera& camera, size_t pixels)
    : CudaHashedFilter(settings, hashed_filter_pixel_angle(camera), pixels) {}

CudaHashedFilter::CudaHashedFilter(const HashedFilterSettings& settings, float pixel_angle, size_t pixels)
    : settings_(settings) {
  check_hashed_filter_settings(settings, FilterDevice::cuda);
  settings_.key.pixel_angle = pixel_angle;  // as HashedFilter: sec. 4, s times the projected pixel size
  steps_ = pathspace::step_settings(settings_);
  pixels_ = pixels;
  cells_ = hashed_filter_table_cells(settings_, pixels);  // HashedFilter's table size
  fingerprints_.resize(cells_);
  cells_buffer_.resize(cells_);
  if (settings_.multi_level) {
    coarse_fingerprints_.resize(cells_);
    coarse_cells_.resize(cells_);
  }
  counters_.resize(size_t(kCounters) * kCopies);
  stats_.device = FilterDevice::cuda;
  stats_.cells = cells_;
  stats_.table_bytes = size_t(cells_) * (sizeof(uint32_t) + sizeof(VoxelCell)) * (settings_.multi_level ? 2 : 1);
  if (settings_.temporal.enabled()) {
    // Sec. 3.4: the keys stay from pass to pass (the table starts empty), beside a history per cell.
    fingerprints_.fill_bytes(0);
    history_.resize(cells_);
    history_.fill_bytes(0);
    transferred_.resize(cells_);
    transfer_claimed_.resize(cells_);
    transfer_claimed_.fill_bytes(0);
    stats_.temporal = true;
    stats_.table_bytes += history_.bytes() + transferred_.bytes() + transfer_claimed_.bytes();
  }
}

void CudaHashedFilter::begin_frame(const PerspectiveCamera& camera) {
  if (size_t(camera.width) * size_t(camera.height) != pixels_) throw Error("the hashed filter's frames must keep one image size");
  settings_.key.pixel_angle = hashed_filter_pixel_angle(camera);
  steps_ = pathspace::step_settings(settings_);
}

void CudaHashedFilter::statistics(Statistics& out) const { report_statistics(stats_, HashedStatsScope{}, out); }

VoxelHashTableView CudaHashedFilter::table() const {
  VoxelHashTableView v;
  v.fingerprints = const_cast<uint32_t*>(fingerprints_.data());
  v.cells = const_cast<VoxelCell*>(cells_buffer_.data());
  v.mask = cells_ - 1;
  v.max_probes = settings_.max_probes;
  if (settings_.temporal.enabled()) v.key_mask = kKeyBitsMask;  // priorities in the top bits (sec. 3.4.3)
  return v;
}

VoxelHashTableView CudaHashedFilter::coarse_table() const {
  if (!settings_.multi_level) return VoxelHashTableView{};
  VoxelHashTableView v = table();
  v.fingerprints = const_cast<uint32_t*>(coarse_fingerprints_.data());
  v.cells = const_cast<VoxelCell*>(coarse_cells_.data());
  return v;
}

// The pass's counters so far, summed over the copies (waits for the stream).
std::vector<unsigned long long> CudaHashedFilter::read_counters(cudaStream_t stream) const {
  std::vector<unsigned long long> copies(counters_.size()), sums(kCounters, 0);
  PS_CUDA_CHECK(cudaMemcpyAsync(copies.data(), counters_.data(), counters_.bytes(), cudaMemcpyDeviceToHost, stream));
  PS_CUDA_CHECK(cudaStreamSynchronize(stream));
  for (int copy = 0; copy < kCopies; ++copy)
    for (int k = 0; k < kCounters; ++k) {
      const unsigned long long v = copies[size_t(copy) * kCounters + k];
      sums[k] = k == kProbesMax ? std::max(sums[k], v) : sums[k] + v;
    }
  return sums;
}

// CudaHashedFilter's steps of the pass (hashed_pass.h): kernels on one stream over device memory,
// timed by events; the counters are read back when the settling needs them and at the end.
class CudaHashedFilter::PassSteps final : public HashedPassSteps {
 public:
  PassSteps(CudaHashedFilter& f, const VertexBufferView& b, Rgb* filtered, cudaStream_t stream)
      : f_(f), b_(b), filtered_(filtered), stream_(stream), table_(f.table()), coarse_(f.coarse_table()) {
    for (cudaEvent_t& e : events_) PS_CUDA_CHECK(cudaEventCreate(&e));
  }
  ~PassSteps() override {
    for (cudaEvent_t e : events_)
      if (e) cudaEventDestroy(e);
  }
  PassSteps(const PassSteps&) = delete;
  PassSteps& operator=(const PassSteps&) = delete;

  void mark(PassMark at) override { PS_CUDA_CHECK(cudaEventRecord(events_[int(at)], stream_)); }
  // One memset per array; with --temporal the keys stay, so that they find their history.
  void clear() override {
    if (!f_.settings_.temporal.enabled()) PS_CUDA_CHECK(cudaMemsetAsync(f_.fingerprints_.data(), 0, f_.fingerprints_.bytes(), stream_));
    PS_CUDA_CHECK(cudaMemsetAsync(f_.cells_buffer_.data(), 0, f_.cells_buffer_.bytes(), stream_));
    if (f_.settings_.multi_level) {
      PS_CUDA_CHECK(cudaMemsetAsync(f_.coarse_fingerprints_.data(), 0, f_.coarse_fingerprints_.bytes(), stream_));
      PS_CUDA_CHECK(cudaMemsetAsync(f_.coarse_cells_.data(), 0, f_.coarse_cells_.bytes(), stream_));
    }
    PS_CUDA_CHECK(cudaMemsetAsync(f_.counters_.data(), 0, f_.counters_.bytes(), stream_));
  }
  void accumulate(uint64_t pass_hash) override {
    if (b_.slots() == 0) return;
    accumulate_kernel<<<blocks_for(b_.slots()), kBlock, 0, stream_>>>(f_.steps_, b_, pass_hash, table_, coarse_, f_.slots_.data(),
                                                                      coarse_slots(), f_.counters_.data());
    PS_CUDA_CHECK_LAUNCH("accumulate_kernel");
  }
  uint64_t probe_failures() override { return f_.read_counters(stream_)[kFailures]; }
  bool settle_overflows(uint64_t pass_hash, uint64_t failures) override {
    return f_.settle_overflows(b_, pass_hash, failures, stream_);
  }
  void list_step_cells() override {}  // the kernels below visit the whole table
  void transfer_levels(uint64_t pass_hash, uint32_t step) override {
    if (b_.slots() > 0) f_.transfer_levels(b_, pass_hash, step, stream_);
  }
  void exchange_probes(uint64_t, uint32_t) override {
    throw Error("the GPU hashed filter has no --temporal hybrid (check_hashed_filter_settings refuses it)");
  }
  void lookup(uint64_t pass_hash) override {
    if (b_.slots() == 0) return;
    const bool temporal = f_.settings_.temporal.enabled();
    lookup_kernel<<<blocks_for(b_.slots()), kBlock, 0, stream_>>>(f_.steps_, b_, pass_hash, table_, coarse_, f_.slots_.data(),
                                                                  coarse_slots(), f_.settings_.temporal,
                                                                  temporal ? f_.history_.data() : nullptr, filtered_,
                                                                  f_.counters_.data());
    PS_CUDA_CHECK_LAUNCH("lookup_kernel");
  }
  void end_step(uint32_t step) override { f_.end_step(step, stream_); }
  HashedPassCounts finish() override {
    occupancy_kernel<<<blocks_for(f_.cells_), kBlock, 0, stream_>>>(f_.fingerprints_.data(), f_.cells_, f_.counters_.data());
    PS_CUDA_CHECK_LAUNCH("occupancy_kernel");
    const std::vector<unsigned long long> c = f_.read_counters(stream_);
    HashedPassCounts n;
    n.vertices = c[kVertices];
    n.not_accumulated = c[kNotAccumulated];
    n.insertions = c[kInsertions];
    n.probes = c[kProbes];
    n.probes_max = c[kProbesMax];
    n.failures = c[kFailures] + c[kLost] - c[kWon];
    n.low_count = c[kLowCount];
    n.neighbour_lookups = c[kNeighbourLookups];
    n.multi_level_used = c[kMultiLevelUsed];
    n.occupied_cells = c[kOccupied];
    n.blended = c[kBlended];
    n.alpha_fixed = c[kAlphaSum];
    n.from_finer = c[kFromFiner];
    n.from_coarser = c[kFromCoarser];
    n.folded = c[kFolded];
    n.evicted = c[kEvicted];
    return n;
  }
  double milliseconds(PassMark from, PassMark to) const override {
    float t = 0.f;
    PS_CUDA_CHECK(cudaEventElapsedTime(&t, events_[int(from)], events_[int(to)]));
    return double(t);
  }

 private:
  int32_t* coarse_slots() const { return f_.settings_.multi_level ? f_.coarse_slots_.data() : nullptr; }

  CudaHashedFilter& f_;
  const VertexBufferView b_;
  Rgb* filtered_;
  cudaStream_t stream_;
  const VoxelHashTableView table_, coarse_;
  cudaEvent_t events_[int(PassMark::count)] = {};
};

void CudaHashedFilter::filter(const VertexBufferView& b, uint64_t seed, uint32_t pass, Rgb* device_filtered,
                              cudaStream_t stream) {
  if (b.records_per_path < 1 && b.paths > 0) throw Error("CudaHashedFilter::filter: a vertex buffer without record slots");
  const size_t slots = b.slots();
  if (slots > size_t(INT32_MAX)) throw Error("CudaHashedFilter::filter: more than 2^31 record slots in one batch");
  if (slots_.size() < slots) slots_.resize(slots);
  if (settings_.multi_level && coarse_slots_.size() < slots) coarse_slots_.resize(slots);
  PassSteps steps(*this, b, device_filtered, stream);
  run_hashed_pass(steps, settings_, seed, pass, &stats_);
}

void CudaHashedFilter::filter(const VertexBuffer& buffer, uint64_t seed, uint32_t pass, SlotValues* filtered) {
  host_buffer_.upload(buffer);
  const VertexBufferView view = host_buffer_.view();
  host_filtered_.resize(view.slots());
  filter(view, seed, pass, host_filtered_.data());
  filtered->resize(view.slots());
  host_filtered_.download(filtered->data(), view.slots());
}

// hashed_filter_overflow.cpp on the GPU's table: the failed vertices are listed on the device, the
// decision is the CPU's own code (overflow_settling.cpp) on the downloaded fingerprints, and its
// result is applied by kernels. Rare (a table too small for the pass), so plain copies are fine.
bool CudaHashedFilter::settle_overflows(const VertexBufferView& b, uint64_t pass_hash, uint64_t failures, cudaStream_t stream) {
  const VoxelHashTableView table = this->table();
  unsigned long long* counters = counters_.data();
  DeviceBuffer<FailedVertex> failed_device{size_t(failures)};
  list_failed_kernel<<<blocks_for(b.slots()), kBlock, 0, stream>>>(steps_, b, pass_hash, table, slots_.data(),
                                                                    failed_device.data(), failures, counters);
  PS_CUDA_CHECK_LAUNCH("list_failed_kernel");
  PS_CUDA_CHECK(cudaStreamSynchronize(stream));
  const std::vector<FailedVertex> failed = failed_device.download();
  const std::vector<uint32_t> fingerprints = fingerprints_.download();
  // As HashedFilter: a cell is new this pass when the table is cleared every pass, or when it has no
  // history yet (--temporal).
  const std::vector<VoxelHistory> history = history_.download();

  std::map<uint64_t, std::vector<uint32_t>> failed_keys;
  for (const FailedVertex& f : failed) failed_keys[f.window].push_back(f.key);
  const OverflowDecision d = decide_overflows(
      std::move(failed_keys), table.key_mask, [&](uint64_t c) { return fingerprints[c]; },
      [&](uint64_t c) { return history.empty() || !(history[c].weight > 0.f); });
  if (d.assigned.empty()) return false;  // as the CPU: nothing changes hands, the pass is not counted as settled

  std::vector<unsigned long long> assigned_cells;
  std::vector<uint32_t> assigned_keys;
  for (const auto& [cell, key] : d.assigned) assigned_cells.push_back(cell), assigned_keys.push_back(key);
  std::vector<uint32_t> winner_keys;  // sorted (a std::map's order), one cell each
  std::vector<unsigned long long> winner_cells;
  for (const auto& [key, cell] : d.cell_of_key) winner_keys.push_back(key), winner_cells.push_back(cell);
  const DeviceBuffer<unsigned long long> assigned_cells_device(assigned_cells), winner_cells_device(winner_cells);
  const DeviceBuffer<uint32_t> assigned_keys_device(assigned_keys), winner_keys_device(winner_keys);
  if (reassigned_.size() != cells_) reassigned_.resize(cells_);
  PS_CUDA_CHECK(cudaMemsetAsync(reassigned_.data(), 0, reassigned_.bytes(), stream));

  reassign_kernel<<<blocks_for(assigned_cells.size()), kBlock, 0, stream>>>(
      table, assigned_cells_device.data(), assigned_keys_device.data(), assigned_cells.size(), reassigned_.data());
  PS_CUDA_CHECK_LAUNCH("reassign_kernel");
  drop_losers_kernel<<<blocks_for(b.slots()), kBlock, 0, stream>>>(b, slots_.data(), reassigned_.data(), counters);
  PS_CUDA_CHECK_LAUNCH("drop_losers_kernel");
  add_winners_kernel<<<blocks_for(failed.size()), kBlock, 0, stream>>>(
      steps_, b, table, failed_device.data(), failed.size(), winner_keys_device.data(), winner_cells_device.data(),
      winner_keys.size(), slots_.data(), counters);
  PS_CUDA_CHECK_LAUNCH("add_winners_kernel");
  // The device buffers above are freed on return: wait for the kernels that read them.
  PS_CUDA_CHECK(cudaStreamSynchronize(stream));
  return true;
}

}  // namespace pathspace::gpu
