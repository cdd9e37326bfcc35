// Hashed path space filtering (Binder, Fricke, Keller 2021, sec. 3.1-3.3) on the CPU: per pass, every
// selected vertex is quantised to a jittered voxel key (algorithm 1), accumulated into a hash table by
// atomic adds (sec. 3.2), and then looks up its voxel's average; low-count voxels optionally use a
// neighbourhood search (3.3.1) or a coarser level (3.3.2); vertices that cannot be inserted keep their
// unfiltered contribution. Statistics and debug images (AOVs) show what the table did. The pass's
// sequence is run_hashed_pass (hashed_pass.h), shared with the GPU filter; this class holds the
// steps' TBB implementations.
#pragma once

#include <tbb/enumerable_thread_specific.h>

#include <memory>
#include <vector>

#include "pathspace/camera/perspective_camera.h"
#include "pathspace/film/image.h"
#include "pathspace/filters/hashed/hashed_filter_settings.h"
#include "pathspace/filters/hashed/hashed_filter_stats.h"
#include "pathspace/filters/hashed/hashed_filter_steps.h"
#include "pathspace/filters/hashed/hashed_pass.h"
#include "pathspace/filters/hashed/local_voxel_cache.h"
#include "pathspace/filters/path_space_filter.h"
#include "pathspace/filters/hashed/temporal_history.h"
#include "pathspace/filters/hashed/voxel_hash_table.h"

namespace pathspace {

// Debug images of the first record of each path (sec. 3.1, fig. 3 and 5 style visualisations); with
// --temporal also the voxel's history (sec. 3.4): `history`, the vertices behind it (N_old after
// this step: its age counted in vertices), and `alpha`, the history's weight in this step's average.
enum class FilterAov { voxel, count, level, probes, history, alpha };

class HashedFilter final : public PathSpaceFilter {
 public:
  HashedFilter(const HashedFilterSettings& settings, const PerspectiveCamera& camera, size_t pixels);

  const char* name() const override { return "hashed"; }
  std::string distribution_limit() const override {
    if (history_) return kTemporalDistributionLimit;
    return settings_.adaptive ? "--psf-adaptive carries each pass's choice of voxel level to the next pass" : std::string();
  }
  // With --psf-adaptive a frame's first pass takes the choices of the previous frame's last pass:
  // one frame before gives exactly that state. Otherwise every pass starts afresh.
  uint32_t frame_warm_up() const override {
    if (history_) return kTemporalWarmUpFrames;
    return settings_.adaptive ? 1 : 0;
  }
  // --psf-aa-paths: query-only camera paths (2014 paper, sec. 3) read the table the pass left;
  // --psf-caustic-photons: caustic paths come from a photon map, not from the voxel averages.
  FilterNeeds needs() const override {
    FilterNeeds n;
    n.query_paths = settings_.aa_paths;
    n.caustics = settings_.caustics;
    return n;
  }
  void filter(const VertexBuffer& buffer, uint64_t seed, uint32_t pass, SlotValues* filtered) override;
  void query(const VertexBuffer& queries, SlotValues* values, std::vector<uint8_t>* found) override;
  void statistics(Statistics& out) const override;
  // The debug images (voxel, count, level, probes; history and alpha with --temporal) when
  // settings.debug_images is on.
  std::vector<NamedImage> aovs() const override;
  void save_state(StateWriter& out) const override;
  void load_state(StateReader& in) override;
  void begin_frame(const PerspectiveCamera& camera) override;
  const ProbeRequest* probe_request(uint32_t pass) const override;
  void temporal_probes(const VertexBuffer& probes) override;

  const HashedFilterStats& stats() const { return stats_; }
  const TemporalHistory* history() const { return history_.get(); }
  void reset_stats();
  const VoxelHashTable& table() const { return table_; }
  // AOV of the last filtered pass (width x height of the camera); needs settings.debug_images.
  Image aov(FilterAov which) const;
  bool has_debug_images() const { return settings_.debug_images; }

  // Key of a record (exposed for tests and benchmarks).
  VoxelKey key_of(const VertexBuffer& buffer, size_t slot, uint64_t seed, uint32_t pass) const;

 private:
  static constexpr size_t kGrain = 2048;  // paths per parallel_for chunk of the per-vertex steps
  class PassSteps;  // the steps of run_hashed_pass, over this object (hashed_filter.cpp)
  VoxelKey key_for_pass(const VertexBuffer& buffer, size_t slot, uint64_t pass_hash) const;
  bool keeps_keys() const { return settings_.debug_images || settings_.neighbour_search; }
  void clear_table();
  void accumulate(const VertexBuffer& buffer, uint64_t pass_hash);
  void lookup(const VertexBuffer& buffer, SlotValues* filtered);
  // A vertex's estimate in fine cell `slot` from the cell's `average` (this pass's, or blended with
  // its history): the coarse cell where sec. 3.1.3 chose it, else the low-count steps of sec. 3.3.
  // `key` is read only by the neighbour search, `coarse_slot` only with a coarse table.
  Rgb level_estimate(int32_t slot, int32_t coarse_slot, const VoxelKey& key, const Rgb& average, const HashedStepSettings& steps,
                     LookupCounters* counters) const;
  // Hybrid (sec. 3.4.1): the re-traced paths' changes into their cells, and this frame's values of
  // the paths the next frame re-traces.
  void exchange_probes(const VertexBuffer& buffer, uint64_t seed, uint32_t pass);
  void apply_probes(const VertexBuffer& probes, uint64_t pass_hash);
  void record_probe_originals(const VertexBuffer& buffer, uint64_t seed, uint32_t pass);
  // The debug images' record of each pixel (its first path's first record).
  void record_first_slots(const VertexBuffer& buffer);
  // After accumulation, when probe windows overflowed: which keys get the window's new cells is
  // decided by their fingerprints, not by thread timing (hashed_filter_overflow.cpp). True when cells
  // changed hands.
  bool settle_overflows(const VertexBuffer& buffer, uint64_t pass_hash);
  // The cells of the step, once each, from table_records_ (or from every record,
  // step_cells_from_all_vertices) into step_cells_.
  void gather_step_cells(const VertexBuffer& buffer);
  // Sec. 3.4.2: new cells take the history of the same point at the next finer or coarser level.
  void transfer_levels(const VertexBuffer& buffer, uint64_t pass_hash, uint32_t step);
  // Sec. 3.4.1: the blend of every cell of step_cells_ into cell_blends_, before the lookup.
  void blend_cells();

  HashedFilterSettings settings_;
  int width_, height_;
  VoxelHashTable table_;
  std::unique_ptr<VoxelHashTable> coarse_table_;  // multi-level or adaptive accumulation
  std::vector<uint64_t> coarse_squares_;          // adaptive: per coarse cell, its vertices' squared luminance (fixed point)
  // Adaptive (sec. 3.1.3): each record slot's fine voxel (voxel_identity), and the fine voxels whose
  // vertices take the fine average in this pass, chosen after the previous pass from its cells
  // (choices made on the same vertices they average would favour the outliers: a biased image).
  std::vector<uint64_t> fine_voxel_;
  std::vector<uint64_t> refined_voxels_;  // sorted
  // Per fine cell in this pass (map_cells): its voxel, its coarse cell, and flags.
  static constexpr uint8_t kCellFine = 1, kCellShared = 2;  // take the fine average; two voxels collide here
  std::vector<uint64_t> cell_voxel_;
  std::vector<int32_t> cell_coarse_;
  std::vector<uint8_t> cell_flags_;
  void map_cells(const VertexBuffer& b);
  void choose_levels();
  std::unique_ptr<TemporalHistory> history_;      // sec. 3.4: null unless --temporal
  // Per record slot, for the lookup phase and the AOVs.
  std::vector<VoxelKey> keys_;
  // Table cell per record slot (< 0: not in the table): accumulate writes it for every record, and
  // only records read it, so slots without a record stay unwritten and their pages untouched.
  UninitializedVector<int32_t> slots_, coarse_slots_;
  // accumulate()'s combining cache per thread (1 MiB each), kept from pass to pass: made anew,
  // every pass of an animation paid for allocating, zeroing and faulting them in. Each pass's
  // flush_all leaves them empty.
  tbb::enumerable_thread_specific<LocalVoxelCache> caches_;
  std::vector<uint16_t> probes_;
  std::vector<uint32_t> counts_;
  std::vector<uint32_t> first_slot_of_pixel_;
  HashedFilterStats stats_;
  HashedPassCounts pass_counts_;  // the current pass's, filled by its steps
  uint64_t pass_hash_ = 0;      // the last filtered pass's jitter hash, which its queries mix with
  uint32_t query_round_ = 0;    // query paths of that pass so far (each round has its own jitter)
  // Frames and temporal finite differences (--temporal hybrid).
  PerspectiveCamera camera_;       // of the current frame
  uint64_t frame_ = 0;             // frames begun before this one
  bool frame_started_ = false;
  ProbeRequest probe_request_;     // this frame's re-traced paths (pass 0), while has_probe_request_
  bool has_probe_request_ = false;
  std::vector<float> probe_originals_;  // their luminance in the previous frame (NaN: no vertex)
  const VertexBuffer* pending_probes_ = nullptr;
  ProbeRequest next_request_;      // recorded in this frame's pass 0 for the next frame
  std::vector<float> next_originals_;
  // Per thread: the record slots whose vertex reached the table itself in accumulate() (not
  // combined in the thread's cache) or got a cell in the overflow settling. They include a vertex of
  // every cell of the step, so the step's cells are found among these (a few thousand in a 640x360
  // frame), not among all vertices.
  tbb::enumerable_thread_specific<std::vector<size_t>> table_records_;
  // The cells the step used, each once, with one of its records (gather_step_cells): the level
  // transfer looks for new cells, the blend visits cells and, when they are few, the next step
  // clears only these (the whole table took 0.45 ms of a 640x360 frame).
  std::vector<uint32_t> step_cells_;
  std::vector<size_t> step_cell_records_;
  bool step_cells_clear_listed_ = false;
  std::vector<uint8_t> cell_listed_;  // all zero between steps
  // Sec. 3.4.2: phase 1 of transfer_levels, per step cell.
  struct CellTransfer {
    LevelTransfer kind = LevelTransfer::none;
    VoxelHistory history;
  };
  std::vector<CellTransfer> transfers_;
  // Sec. 3.4.1: each step cell's blend of this step's average with its history (blend_cells), read
  // by the lookup's vertices.
  struct CellBlend {
    Rgb average;
    float alpha = 0.f;
  };
  std::vector<CellBlend> cell_blends_;
};

}  // namespace pathspace
