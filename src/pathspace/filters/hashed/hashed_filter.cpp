#include "pathspace/filters/hashed/hashed_filter.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for_each.h>


#include "pathspace/base/error.h"
#include "pathspace/filters/hashed/hashed_filter_keys.h"
#include "pathspace/filters/hashed/hashed_filter_steps.h"
#include "pathspace/filters/hashed/hashed_filter_limits.h"
#include "pathspace/filters/hashed/local_voxel_cache.h"
#include "pathspace/filters/hashed/voxel_key_blocks.h"
#include "pathspace/filters/hashed/voxel_key_batch.h"
#include "pathspace/parallel/parallel_for.h"

namespace pathspace {

namespace {

constexpr int32_t kNotAccumulated = kSlotNotAccumulated;  // contribution not representable (NaN, negative, huge)

// Counters gathered per parallel_for chunk and summed once per chunk.
struct AccumulateCounters {
  std::atomic<uint64_t> vertices{0}, insertions{0}, failures{0}, not_accumulated{0}, probes{0}, probes_max{0};
  void add(uint64_t v, uint64_t ins, uint64_t f, uint64_t na, uint64_t p, uint64_t pmax) {
    vertices += v;
    insertions += ins;
    failures += f;
    not_accumulated += na;
    probes += p;
    uint64_t seen = probes_max.load();
    while (pmax > seen && !probes_max.compare_exchange_weak(seen, pmax)) {
    }
  }
};

Rgb voxel_colour(const VoxelKey& k) {
  const uint64_t h = hash_voxel_key(k, NormalKeyMode::key).index;
  return {0.1f + 0.9f * bits_to_unit_float(h), 0.1f + 0.9f * bits_to_unit_float(h << 24),
          0.1f + 0.9f * bits_to_unit_float(mix64(h))};
}

}  // namespace

HashedFilter::HashedFilter(const HashedFilterSettings& settings, const PerspectiveCamera& camera, size_t pixels)
    : settings_(settings),
      width_(camera.width),
      height_(camera.height),
      table_(hashed_filter_table_cells(settings, pixels), settings.max_probes),
      camera_(camera) {
  check_hashed_filter_settings(settings, FilterDevice::cpu);
  settings_.key.pixel_angle = hashed_filter_pixel_angle(camera);
  if (settings.multi_level || settings.adaptive) coarse_table_ = std::make_unique<VoxelHashTable>(table_.cells(), settings.max_probes);
  if (settings.adaptive) coarse_squares_.resize(table_.cells());
  if (settings.temporal.enabled()) {
    table_.keep_across_frames();
    history_ = std::make_unique<TemporalHistory>(settings.temporal, table_.cells());
  }
  stats_.temporal = history_ != nullptr;
  stats_.cells = table_.cells();
  stats_.table_bytes = table_.bytes() + (coarse_table_ ? coarse_table_->bytes() : 0) + (history_ ? history_->bytes() : 0) +
                       coarse_squares_.size() * sizeof(uint64_t);
}

void HashedFilter::begin_frame(const PerspectiveCamera& camera) {
  if (camera.width != width_ || camera.height != height_) throw Error("the hashed filter's frames must keep one image size");
  settings_.key.pixel_angle = hashed_filter_pixel_angle(camera);
  // Hybrid: the previous frame's pass 0 recorded the paths to re-trace now, with its camera.
  has_probe_request_ = !next_request_.pixels.empty();
  if (has_probe_request_) {
    probe_request_ = std::move(next_request_);
    probe_request_.camera = camera_;
    probe_originals_ = std::move(next_originals_);
    next_request_ = ProbeRequest{};
    next_originals_.clear();
  }
  if (frame_started_) ++frame_;
  frame_started_ = true;
  camera_ = camera;
}

const ProbeRequest* HashedFilter::probe_request(uint32_t pass) const {
  return has_probe_request_ && pass == probe_request_.pass ? &probe_request_ : nullptr;
}

void HashedFilter::temporal_probes(const VertexBuffer& probes) { pending_probes_ = &probes; }

namespace {
// The pixels re-traced in frame f: a pseudo-random 1 / period of them, another share each frame, so
// every pixel takes its turn once in `period` frames (the cost amortised over frames, sec. 3.4.1).
bool probed_in_frame(uint32_t pixel, uint64_t frame, uint64_t period) { return mix64(uint64_t(pixel) ^ 0x7072626eull) % period == frame % period; }
}  // namespace

void HashedFilter::apply_probes(const VertexBuffer& probes, uint64_t pass_hash) {
  const VoxelHashTableView view = table_.view();
  double change = 0.0;
  uint64_t found = 0, traced = 0;
  // Serial, in probe order: the sums do not depend on the thread count.
  for (size_t k = 0; k < probes.paths() && k < probe_originals_.size(); ++k) {
    if (probes.count[k] == 0 || std::isnan(probe_originals_[k])) continue;
    ++traced;
    const size_t i = probes.slot(k, 0);
    const ProbeResult r = view.find(hash_voxel_key(key_for_pass(probes, i, pass_hash), settings_.key.normal));
    if (r.slot < 0) continue;
    const float before = probe_originals_[k], now = luminance(probes.contribution[i]);
    if (!std::isfinite(now)) continue;
    history_->add_change(uint64_t(r.slot), before, now);
    ++found;
    change += std::fabs(now - before) / std::max(1e-30f, std::max(std::fabs(now), std::fabs(before)));
  }
  stats_.probes += traced;
  stats_.probes_found += found;
  stats_.change_sum += change;
}

void HashedFilter::gather_step_cells(const VertexBuffer& b) {
  if (cell_listed_.size() != size_t(table_.cells())) cell_listed_.assign(size_t(table_.cells()), 0);
  step_cells_.clear();
  step_cell_records_.clear();
  const auto add = [&](size_t i) {
    const int32_t s = slots_[i];  // < 0: no cell, or one the overflow settling gave to another key
    if (s < 0 || cell_listed_[size_t(s)]) return;
    cell_listed_[size_t(s)] = 1;
    step_cells_.push_back(uint32_t(s));
    step_cell_records_.push_back(i);
  };
  for (std::vector<size_t>& records : table_records_) {
    if (!settings_.step_cells_from_all_vertices)
      for (const size_t i : records) add(i);
    records.clear();
  }
  if (settings_.step_cells_from_all_vertices)
    for (size_t path = 0; path < b.paths(); ++path)
      for (int r = 0; r < b.count[path]; ++r) add(b.slot(path, r));
  for (const uint32_t c : step_cells_) cell_listed_[c] = 0;
  // Beyond a sixteenth of the table, clearing it whole (parallel, streaming) is no slower.
  step_cells_clear_listed_ = !settings_.step_cells_from_all_vertices && step_cells_.size() <= size_t(table_.cells()) / 16;
}

void HashedFilter::transfer_levels(const VertexBuffer& b, uint64_t pass_hash, uint32_t step) {
  transfers_.resize(step_cells_.size());
  // Phase 1: each new cell (no history) computes its transfer from the histories as they were, from
  // any of its records (every vertex of a cell has the same key).
  parallel_for(step_cells_.size(), 256, [&](size_t begin, size_t end) {
    for (size_t k = begin; k < end; ++k) {
      transfers_[k].kind = LevelTransfer::none;
      if (history_->at(step_cells_[k]).weight > 0.f) continue;
      transfers_[k].kind = level_transfer(settings_.temporal, table_.view(), history_->cells().data(), settings_.key.normal,
                                          key_for_pass(b, step_cell_records_[k], pass_hash), step,
                                          &transfers_[k].history);
    }
  });
  // Phase 2: the transfers take effect.
  for (size_t k = 0; k < step_cells_.size(); ++k) {
    if (transfers_[k].kind == LevelTransfer::none) continue;
    history_->transfer(step_cells_[k], transfers_[k].history);
    ++(transfers_[k].kind == LevelTransfer::from_finer ? pass_counts_.from_finer : pass_counts_.from_coarser);
  }
}

void HashedFilter::record_probe_originals(const VertexBuffer& b, uint64_t seed, uint32_t pass) {
  const uint64_t period = uint64_t(std::max(1.0, std::round(1.0 / double(settings_.temporal.probe_fraction))));
  next_request_ = ProbeRequest{};
  next_request_.seed = seed;
  next_request_.pass = pass;
  next_originals_.clear();
  for (size_t path = 0; path < b.paths(); ++path) {
    if (!probed_in_frame(b.pixel[path], frame_ + 1, period)) continue;
    next_request_.pixels.push_back(b.pixel[path]);
    next_originals_.push_back(b.count[path] > 0 ? luminance(b.contribution[b.slot(path, 0)]) : std::nanf(""));
  }
}

void HashedFilter::reset_stats() { stats_ = stats_.fresh(); }

VoxelKey HashedFilter::key_of(const VertexBuffer& b, size_t i, uint64_t seed, uint32_t pass) const {
  return key_for_pass(b, i, pass_jitter_hash(seed, pass));
}

// The scalar reference of the batched keys used by accumulate() (voxel_key_batch.h), shared with the
// GPU (hashed_filter_keys.h).
VoxelKey HashedFilter::key_for_pass(const VertexBuffer& b, size_t i, uint64_t pass_hash) const {
  return pathspace::key_for_pass(settings_.key, b.view(), i, pass_hash);
}

// HashedFilter's steps of the pass (hashed_pass.h): TBB over host memory.
class HashedFilter::PassSteps final : public HashedPassSteps {
 public:
  PassSteps(HashedFilter& f, const VertexBuffer& b, SlotValues* filtered) : f_(f), b_(b), filtered_(filtered) {}
  void mark(PassMark at) override { times_[int(at)] = std::chrono::steady_clock::now(); }
  void clear() override { f_.clear_table(); }
  void accumulate(uint64_t pass_hash) override { f_.accumulate(b_, pass_hash); }
  uint64_t probe_failures() override { return f_.pass_counts_.failures; }
  bool settle_overflows(uint64_t pass_hash, uint64_t) override { return f_.settle_overflows(b_, pass_hash); }
  void list_step_cells() override { f_.gather_step_cells(b_); }
  void transfer_levels(uint64_t pass_hash, uint32_t step) override { f_.transfer_levels(b_, pass_hash, step); }
  void exchange_probes(uint64_t seed, uint32_t pass) override { f_.exchange_probes(b_, seed, pass); }
  void lookup(uint64_t) override {
    if (f_.settings_.adaptive) f_.map_cells(b_);
    f_.lookup(b_, filtered_);
    if (f_.settings_.adaptive) f_.choose_levels();
    if (f_.settings_.debug_images) f_.record_first_slots(b_);
  }
  void end_step(uint32_t step) override {
    const TemporalStepStats s = f_.history_->end_step(f_.table_.view(), step);
    f_.pass_counts_.folded = s.folded;
    f_.pass_counts_.evicted = s.evicted;
  }
  HashedPassCounts finish() override {
    const VoxelTableOccupancy occ = f_.table_.occupancy();
    f_.pass_counts_.occupied_cells = occ.occupied;
    f_.pass_counts_.expected_fingerprint_collisions = occ.expected_fingerprint_collisions;
    return f_.pass_counts_;
  }
  double milliseconds(PassMark from, PassMark to) const override {
    return std::chrono::duration<double, std::milli>(times_[int(to)] - times_[int(from)]).count();
  }

 private:
  HashedFilter& f_;
  const VertexBuffer& b_;
  SlotValues* filtered_;
  std::chrono::steady_clock::time_point times_[int(PassMark::count)];
};

void HashedFilter::filter(const VertexBuffer& buffer, uint64_t seed, uint32_t pass, SlotValues* filtered) {
  const size_t slots = buffer.paths() * size_t(buffer.records_per_path());
  // Per-slot keys, probe counts and voxel counts are kept only when something reads them after
  // accumulation (neighbour search, debug images): storing them cost ~10% of the accumulation.
  keys_.resize(keeps_keys() ? slots : 0);
  fine_voxel_.resize(settings_.adaptive ? slots : 0);
  probes_.resize(settings_.debug_images ? slots : 0);
  counts_.resize(settings_.debug_images ? slots : 0);
  slots_.resize(slots);
  coarse_slots_.resize(coarse_table_ ? slots : 0);
  filtered->resize(slots);
  pass_hash_ = pass_jitter_hash(seed, pass);
  query_round_ = 0;
  pass_counts_ = HashedPassCounts{};
  PassSteps steps(*this, buffer, filtered);
  run_hashed_pass(steps, settings_, seed, pass, &stats_);
}

void HashedFilter::clear_table() {
  // The keys stay in a table kept across frames: they find their history (sec. 3.4).
  if (step_cells_clear_listed_) {  // the last step's cells
    table_.clear_listed(step_cells_, /*keys=*/!history_);
  } else if (history_) {
    table_.clear_sums();
  } else {
    table_.clear();
  }
  if (coarse_table_) coarse_table_->clear();
  std::fill(coarse_squares_.begin(), coarse_squares_.end(), uint64_t(0));
}

void HashedFilter::exchange_probes(const VertexBuffer& buffer, uint64_t seed, uint32_t pass) {
  if (pending_probes_ && has_probe_request_) {
    apply_probes(*pending_probes_, pass_jitter_hash(seed, pass));
    if (settings_.temporal.rectify) history_->rectify();
  }
  pending_probes_ = nullptr;
  has_probe_request_ = false;
  record_probe_originals(buffer, seed, pass);
}

void HashedFilter::record_first_slots(const VertexBuffer& buffer) {
  first_slot_of_pixel_.assign(size_t(width_) * size_t(height_), UINT32_MAX);
  for (size_t path = 0; path < buffer.paths(); ++path)
    if (buffer.count[path] > 0 && buffer.pixel[path] < first_slot_of_pixel_.size())
      first_slot_of_pixel_[buffer.pixel[path]] = uint32_t(buffer.slot(path, 0));
}

void HashedFilter::accumulate(const VertexBuffer& b, uint64_t pass_hash) {
  const VoxelHashTableView view = table_.view();
  const VoxelHashTableView coarse = coarse_table_ ? coarse_table_->view() : VoxelHashTableView{};
  AccumulateCounters counters;
  const bool combine = settings_.local_combining;
  const VoxelKeyIsa isa = widest_voxel_key_isa();
  const bool keep_keys = keeps_keys(), keep_probes = settings_.debug_images;
  const bool adaptive = settings_.adaptive;
  const HashedStepSettings steps = step_settings(settings_);
  for (std::vector<size_t>& records : table_records_) records.clear();
  // One combining cache per thread for the whole pass, not per chunk: a chunk of incoherent
  // (second-bounce) vertices rarely revisits its voxels, the whole pass does (tens of vertices per
  // voxel), so per-chunk caches combined 36% of those vertices and per-thread ones combine most
  // (caches_, kept from pass to pass).
  parallel_for(b.paths(), kGrain, [&](size_t begin, size_t end) {
    uint64_t vertices = 0, insertions = 0, failures = 0, not_accumulated = 0, probes = 0, probes_max = 0;
    LocalVoxelCache& local = caches_.local();
    std::vector<size_t>& table_records = table_records_.local();  // a vertex of each cell of the step
    // Vertices that miss the local cache are queued in a batch whose home cells are prefetched, so
    // that their cache misses overlap instead of being paid one after another (sec. 4: filtering
    // is memory bound; docs/results/cpu-throughput.md, "Machine facts").
    constexpr int kBatch = 16;
    size_t batch[kBatch];
    VoxelHash hashes[kBatch];
    uint64_t fixed_batch[kBatch][3];
    int n = 0;
    auto process_batch = [&] {
      for (int j = 0; j < n; ++j) {
        const size_t i = batch[j];
        LocalVoxelCache::Entry& e = local.entry_for(hashes[j]);
        if (combine && LocalVoxelCache::holds(e, hashes[j])) {  // an earlier vertex of this batch opened it
          slots_[i] = int32_t(LocalVoxelCache::slot(e));
          if (keep_probes) probes_[i] = 0;
          local.add(view, e, fixed_batch[j]);
          continue;
        }
        const ProbeResult pr = view.find_or_insert(hashes[j]);
        ++insertions;
        if (keep_probes) probes_[i] = uint16_t(pr.probes);
        probes += uint64_t(pr.probes);
        probes_max = std::max(probes_max, uint64_t(pr.probes));
        slots_[i] = int32_t(pr.slot);  // -1: probe limit reached
        if (pr.slot < 0) {
          ++failures;
          continue;
        }
        // Whether the cell is new is read in transfer_levels(): here, a cache miss per insertion into
        // the histories made the accumulation 7% slower.
        table_records.push_back(i);
        local.evict(view, e);
        LocalVoxelCache::open(e, hashes[j], uint64_t(pr.slot));
        local.add(view, e, fixed_batch[j]);
        if (!combine) local.evict(view, e);
      }
      n = 0;
    };
    // Keys and hashes are computed for a block of vertices first, eight or sixteen at a time
    // (voxel_key_blocks.h), in a loop without table access; the table work follows per vertex.
    VoxelKeyBlocks blocks(settings_.key, b.view(), begin, end, pass_hash, isa);
    const VoxelKeyBatch& key_batch = blocks.batch();
    int block_n = 0, block_next = 0;
    auto fill_block = [&] {
      block_n = blocks.next();
      block_next = 0;
      for (int j = 0; j < block_n; ++j) {
        if (keep_keys) keys_[blocks.slot(j)] = key_batch.keys[j];
        if (adaptive) fine_voxel_[blocks.slot(j)] = voxel_identity(key_batch.hashes[j]);
        local.prefetch(key_batch.hashes[j]);  // an L2 miss when vertices are incoherent
      }
    };
    for (;;) {
      if (block_next == block_n) {
        fill_block();
        if (block_n == 0) break;
      }
      {
        const int j = block_next++;
        const size_t i = blocks.slot(j);
        const VoxelHash h = key_batch.hashes[j];
        ++vertices;
        uint64_t fixed[3];
        const Rgb value = accumulated_value(steps, b.contribution[i]);
        if (!to_fixed_point(value, fixed)) {
          slots_[i] = kNotAccumulated;
          if (keep_probes) probes_[i] = 0;
          ++not_accumulated;
          continue;
        }
        if (coarse_table_) {
          const ProbeResult cr = coarse.find_or_insert(hash_voxel_key(coarser_key(key_batch.keys[j]), settings_.key.normal));
          coarse_slots_[i] = int32_t(cr.slot);
          if (cr.slot >= 0) {
            coarse.add(uint64_t(cr.slot), fixed);
            if (adaptive) atomic_fetch_add(&coarse_squares_[size_t(cr.slot)], luminance_square_fixed(value));
          }
        }
        LocalVoxelCache::Entry& e = local.entry_for(h);
        if (combine && LocalVoxelCache::holds(e, h)) {
          slots_[i] = int32_t(LocalVoxelCache::slot(e));
          if (keep_probes) probes_[i] = 0;
          local.add(view, e, fixed);
          continue;
        }
        const uint64_t home = h.index & view.mask;
        __builtin_prefetch(&view.fingerprints[home], 1, 3);
        __builtin_prefetch(&view.cells[home], 1, 3);
        hashes[n] = h;
        for (int c = 0; c < 3; ++c) fixed_batch[n][c] = fixed[c];
        batch[n++] = i;
        if (n == kBatch) process_batch();
      }
    }
    process_batch();
    counters.add(vertices, insertions, failures, not_accumulated, probes, probes_max);
  });
  tbb::parallel_for_each(caches_.begin(), caches_.end(), [&](LocalVoxelCache& c) { c.flush_all(view); });
  pass_counts_.vertices = counters.vertices;
  pass_counts_.insertions = counters.insertions;
  pass_counts_.failures = counters.failures;
  pass_counts_.not_accumulated = counters.not_accumulated;
  pass_counts_.probes = counters.probes;
  pass_counts_.probes_max = counters.probes_max.load();
}

// Sec. 3.1.3, before the lookup: each fine cell's voxel, coarse cell and level for this pass. Two
// voxels share a cell only when their fingerprints collide; the cell then takes the smallest voxel
// identity, is marked shared and keeps the coarse level, so nothing depends on which thread wrote
// first.
void HashedFilter::map_cells(const VertexBuffer& b) {
  const size_t cells = size_t(table_.cells());
  cell_voxel_.assign(cells, UINT64_MAX);
  cell_coarse_.assign(cells, kSlotProbeFailed);
  cell_flags_.assign(cells, 0);
  const auto each_vertex = [&](auto&& f) {
    parallel_for(b.paths(), kGrain, [&](size_t begin, size_t end) {
      for (size_t path = begin; path < end; ++path)
        for (int r = 0; r < b.count[path]; ++r) {
          const size_t i = b.slot(path, r);
          if (slots_[i] >= 0) f(i, size_t(slots_[i]));
        }
    });
  };
  each_vertex([&](size_t i, size_t s) {
    std::atomic_ref<uint64_t> voxel(cell_voxel_[s]);
    uint64_t seen = voxel.load(std::memory_order_relaxed);
    while (fine_voxel_[i] < seen && !voxel.compare_exchange_weak(seen, fine_voxel_[i], std::memory_order_relaxed)) {
    }
  });
  each_vertex([&](size_t i, size_t s) {  // the vertices of one voxel have one coarse cell
    if (fine_voxel_[i] == cell_voxel_[s]) {
      std::atomic_ref<int32_t>(cell_coarse_[s]).store(coarse_slots_[i], std::memory_order_relaxed);
    } else {
      std::atomic_ref<uint8_t>(cell_flags_[s]).fetch_or(kCellShared, std::memory_order_relaxed);
    }
  });
  parallel_for(cells, 1 << 14, [&](size_t begin, size_t end) {
    for (size_t s = begin; s < end; ++s)
      if (cell_flags_[s] == 0 && cell_coarse_[s] >= 0 &&
          std::binary_search(refined_voxels_.begin(), refined_voxels_.end(), cell_voxel_[s]))
        cell_flags_[s] = kCellFine;
  });
}

// Sec. 3.1.3, after the lookup: the fine voxels whose vertices take the fine average in the next
// pass, those whose average in this pass has the lower estimated error than its coarse cell's
// (prefer_fine_voxel). Sorted: the same set for any thread count.
void HashedFilter::choose_levels() {
  const VoxelHashTableView view = table_.view(), coarse = coarse_table_->view();
  tbb::enumerable_thread_specific<std::vector<uint64_t>> chosen;
  parallel_for(cell_voxel_.size(), 1 << 14, [&](size_t begin, size_t end) {
    std::vector<uint64_t>& out = chosen.local();
    for (size_t s = begin; s < end; ++s) {
      const int32_t cs = cell_coarse_[s];
      if (cs >= 0 && !(cell_flags_[s] & kCellShared) &&
          prefer_fine_voxel(view.cells[s], coarse.cells[cs], coarse_squares_[size_t(cs)]))
        out.push_back(cell_voxel_[s]);
    }
  });
  std::vector<uint64_t> next;
  for (const std::vector<uint64_t>& v : chosen) next.insert(next.end(), v.begin(), v.end());
  std::sort(next.begin(), next.end());
  refined_voxels_ = std::move(next);
}

Rgb HashedFilter::level_estimate(int32_t slot, int32_t coarse_slot, const VoxelKey& key, const Rgb& average,
                                 const HashedStepSettings& steps, LookupCounters* counters) const {
  const VoxelHashTableView view = table_.view();
  const VoxelHashTableView coarse = coarse_table_ ? coarse_table_->view() : VoxelHashTableView{};
  if (settings_.adaptive) {  // sec. 3.1.3: the fine cell or the coarse one, as chosen after the previous pass
    if (coarse_slot >= 0 && !(cell_flags_[size_t(slot)] & kCellFine)) {
      ++counters->multi_level_used;
      return from_fixed_point(coarse.cells[coarse_slot].sum, coarse.cells[coarse_slot].count);
    }
    return average;
  }
  const VoxelCell& cell = view.cells[slot];
  if (cell.count >= steps.min_count) return average;
  // Sec. 3.3, the steps the GPU runs too (hashed_filter_steps.h).
  return low_count_average(steps, view, coarse, cell, average, key, coarse_slot, counters);
}

void HashedFilter::blend_cells() {
  const VoxelHashTableView view = table_.view();
  if (cell_blends_.size() != size_t(table_.cells())) cell_blends_.resize(size_t(table_.cells()));
  parallel_for(step_cells_.size(), 256, [&](size_t begin, size_t end) {
    for (size_t k = begin; k < end; ++k) {
      CellBlend& b = cell_blends_[step_cells_[k]];
      b.average = history_->blend(step_cells_[k], view.cells[step_cells_[k]], &b.alpha);
    }
  });
}

void HashedFilter::lookup(const VertexBuffer& b, SlotValues* filtered) {
  if (history_) blend_cells();
  const VoxelHashTableView view = table_.view();
  const HashedStepSettings steps = step_settings(settings_);
  const bool keep_counts = settings_.debug_images;
  std::atomic<uint64_t> low_total{0}, neighbour_total{0}, multi_total{0}, blended_total{0};
  std::atomic<uint64_t> alpha_total{0};  // fixed point 2^-32: the sum does not depend on the thread count
  const TemporalHistory* history = history_.get();
  parallel_for(b.paths(), kGrain, [&](size_t begin, size_t end) {
    LookupCounters low_counters;
    uint64_t blended = 0, alpha_sum = 0;
    for (size_t path = begin; path < end; ++path) {
      for (int r = 0; r < b.count[path]; ++r) {
        const size_t i = b.slot(path, r);
        const int32_t s = slots_[i];
        if (s < 0) {
          (*filtered)[i] = b.contribution[i];
          if (keep_counts) counts_[i] = 0;
          continue;
        }
        const VoxelCell& cell = view.cells[s];
        if (keep_counts) counts_[i] = uint32_t(std::min<uint64_t>(cell.count, UINT32_MAX));
        Rgb average;
        if (history) {  // sec. 3.4.1: this step's average blended with what earlier steps left
          const CellBlend& blend = cell_blends_[size_t(s)];
          average = blend.average;
          ++blended;
          alpha_sum += uint64_t(double(blend.alpha) * 4294967296.0);
        } else {
          average = from_fixed_point(cell.sum, cell.count);
        }
        (*filtered)[i] = level_estimate(s, coarse_table_ ? coarse_slots_[i] : kSlotProbeFailed,
                                        settings_.neighbour_search ? keys_[i] : VoxelKey{}, average, steps, &low_counters);
      }
    }
    low_total += low_counters.low_count;
    neighbour_total += low_counters.neighbour_lookups;
    multi_total += low_counters.multi_level_used;
    blended_total += blended;
    alpha_total += alpha_sum;
  });
  pass_counts_.blended = blended_total;
  pass_counts_.alpha_fixed = alpha_total;
  pass_counts_.low_count = low_total;
  pass_counts_.neighbour_lookups = neighbour_total;
  pass_counts_.multi_level_used = multi_total;
}

Image HashedFilter::aov(FilterAov which) const {
  if (!settings_.debug_images) throw Error("the hashed filter's debug images need HashedFilterSettings::debug_images (--aov)");
  if ((which == FilterAov::history || which == FilterAov::alpha) && !history_) throw Error("the history debug images need --temporal");
  Image img(width_, height_);
  for (size_t p = 0; p < first_slot_of_pixel_.size() && p < img.size(); ++p) {
    const uint32_t i = first_slot_of_pixel_[p];
    if (i == UINT32_MAX) continue;
    switch (which) {
      case FilterAov::voxel: img.pixels[p] = voxel_colour(keys_[i]); break;
      case FilterAov::count: img.pixels[p] = Rgb(float(counts_[i])); break;
      case FilterAov::level: img.pixels[p] = Rgb(float(keys_[i].level)); break;
      case FilterAov::probes: img.pixels[p] = Rgb(float(probes_[i])); break;
      case FilterAov::history:
        if (slots_[i] >= 0) img.pixels[p] = Rgb(history_->cells()[size_t(slots_[i])].weight);
        break;
      case FilterAov::alpha:
        if (slots_[i] >= 0) img.pixels[p] = Rgb(cell_blends_[size_t(slots_[i])].alpha);
        break;
    }
  }
  return img;
}

void HashedFilter::statistics(Statistics& out) const {
  const HashedStatsScope scope{.query_paths = settings_.aa_paths > 0,
                               .hybrid = history_ && settings_.temporal.mode == TemporalMode::hybrid,
                               .adaptive = settings_.adaptive,
                               .refined_voxels = refined_voxels_.size()};
  report_statistics(stats_, scope, out);
}

std::vector<NamedImage> HashedFilter::aovs() const {
  // Nothing filtered by this object yet (a render resumed without a new pass): the debug images
  // show the last pass, which a checkpoint does not hold.
  if (!settings_.debug_images || first_slot_of_pixel_.empty()) return {};
  std::vector<NamedImage> images = {{"voxel", aov(FilterAov::voxel)},
                                    {"count", aov(FilterAov::count)},
                                    {"level", aov(FilterAov::level)},
                                    {"probes", aov(FilterAov::probes)}};
  if (history_) {
    images.push_back({"history", aov(FilterAov::history)});
    images.push_back({"alpha", aov(FilterAov::alpha)});
  }
  return images;
}

// Without --temporal the table is rebuilt every pass, so the statistics are the only state a
// continued render needs; with it, the keys with their priorities and the histories too, and with
// --psf-adaptive the voxels whose level the previous pass chose.
void HashedFilter::save_state(StateWriter& out) const {
  out.put("hashed.stats", stats_);
  if (settings_.adaptive) {
    out.put("hashed.adaptive.count", uint64_t(refined_voxels_.size()));
    out.put_vector("hashed.adaptive.refined", refined_voxels_);
  }
  if (!history_) return;
  const VoxelHashTableView v = table_.view();
  out.put_vector("hashed.temporal.fingerprints", std::vector<uint32_t>(v.fingerprints, v.fingerprints + table_.cells()));
  out.put_vector("hashed.temporal.history", history_->cells());
}
void HashedFilter::load_state(StateReader& in) {
  in.get("hashed.stats", &stats_);
  if (settings_.adaptive) {
    uint64_t count = 0;
    in.get("hashed.adaptive.count", &count);
    if (count > table_.cells()) throw Error("checkpoint: more refined voxels than the table has cells");
    in.get_vector("hashed.adaptive.refined", &refined_voxels_, size_t(count));
    if (!std::is_sorted(refined_voxels_.begin(), refined_voxels_.end())) throw Error("checkpoint: the refined voxels are not sorted");
  }
  if (!history_) return;
  std::vector<uint32_t> fingerprints;
  std::vector<VoxelHistory> history;
  in.get_vector("hashed.temporal.fingerprints", &fingerprints, size_t(table_.cells()));
  in.get_vector("hashed.temporal.history", &history, size_t(table_.cells()));
  std::copy(fingerprints.begin(), fingerprints.end(), table_.view().fingerprints);
  history_->restore(std::move(history));
}

}  // namespace pathspace
