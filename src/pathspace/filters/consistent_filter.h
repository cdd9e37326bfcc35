// Consistent path space filtering (Keller, Dahm, Binder 2014): each selected vertex x_i gets the
// average of the contributions of every vertex of its batch inside the ball B(n) around it (eq. 1),
// weighted by binary similarity weights (sec. 2.1), with a radius r(n) = r0 / n^alpha that shrinks
// with the total number n of paths so far (eq. 2), over all passes, batches and resumed renders. So
// the filtered image converges to the unfiltered one and every artefact is transient.
//
// n and r0: r0 is the radius of a disk whose solid angle is that of K x K pixels at the length of
// the camera path to x_i (sec. 2.2), i.e. the radius for one path per pixel, and n counts paths per
// pixel: r(n) = r0 (P / N)^alpha with N paths so far and P pixels. This is eq. 2 with the paper's
// r0 scaled by P^alpha, so that K keeps its meaning in pixels at any image size.
//
// Batches (sec. 2): the paths of a pass are filtered in consecutive batches as large as the memory
// budget allows; every vertex averages over its own batch only. The range search is the project's
// hash grid (hashgrid/), built over the batch's vertices with cells tied to the batch's median
// radius; query and data points are the same set (sec. 2.2). Records are kept in cell order sorted
// by index, so every sum has a fixed order: images are bit-identical for any thread count.
//
// Batches bound the memory: batch_paths() is the number of paths whose vertex buffer, query buffer
// and filtering scratch fit the budget, and the integrator traces, filters and resolves a pass in
// batches of that many paths (pixels in order), so a 4K image never holds a whole pass.
//
// Anti-aliasing (sec. 3, fig. 7): with --psf-aa-paths K, K more camera paths per pixel end at their
// selected vertex and query the batch's vertices (query()): the weighted average of eq. 1 around a
// point that has no contribution of its own; an empty query is not accumulated.
//
// Switch-off (sec. 2.2): once the largest number of averaged contributions in a pass is 1 (every
// ball holds only its own vertex), filtering stops for good; the statistics say after which pass.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "pathspace/camera/perspective_camera.h"
#include "pathspace/filters/consistent_filter_settings.h"
#include "pathspace/filters/consistent_gather.h"
#include "pathspace/filters/path_space_filter.h"
#include "pathspace/hashgrid/hash_grid.h"

namespace pathspace {

struct ConsistentFilterStats {
  uint64_t passes = 0, batches = 0, vertices = 0;
  uint64_t averaged = 0;        // contributions averaged, summed over vertices and iterations
  uint64_t largest_batch = 0;   // records
  uint64_t queries = 0, empty_queries = 0;  // records of query-only paths (--psf-aa-paths)
  uint32_t max_neighbours_last = 0;  // the largest number averaged by one vertex in the last pass
  uint32_t switched_off_after = 0;   // pass count after which filtering stopped; 0: still filtering
  double radius_scale_last = 1.0;    // r / r0 in the last batch
  double filter_ms = 0.0;
};

class ConsistentFilter final : public PathSpaceFilter {
 public:
  ConsistentFilter(const ConsistentFilterSettings& settings, const PerspectiveCamera& camera, size_t pixels);

  const char* name() const override { return "consistent"; }
  FilterNeeds needs() const override;
  size_t batch_paths(int records_per_path) const override;
  void filter(const VertexBuffer& buffer, uint64_t seed, uint32_t pass, SlotValues* filtered) override;
  void end_pass() override;
  void skip_pass(uint64_t paths) override;
  // A distributed render agrees on the switch-off (sec. 2.2) pass by pass, as one process takes it.
  bool reports_passes() const override { return true; }
  uint64_t pass_report() const override { return pass_report_; }
  bool agree_round(const std::vector<uint64_t>& reports, int mine) override;
  // n of eq. 2 and the switch-off carry across frames: a chunk of frames is exact only after all before.
  uint32_t frame_warm_up() const override { return UINT32_MAX; }  // Integrator::kAllFrames
  // A new frame: r0 follows the camera's pixel size; n of eq. 2 goes on counting.
  void begin_frame(const PerspectiveCamera& camera) override;
  void query(const VertexBuffer& queries, SlotValues* values, std::vector<uint8_t>* found) override;
  void statistics(Statistics& out) const override;
  void save_state(StateWriter& out) const override;
  void load_state(StateReader& in) override;

  const ConsistentFilterStats& stats() const { return stats_; }
  // Paths filtered so far (the n of eq. 2, before the next pass).
  uint64_t paths_so_far() const { return paths_so_far_; }
  // Bytes one batch may use, and the records that fit (the batch size).
  size_t batch_memory_bytes() const { return batch_bytes_; }
  static size_t bytes_per_record();

  struct BatchVertex {
    SimilarityKey key;
    Rgb contribution;
    float radius = 0.f;
  };

 private:
  void filter_batch(const VertexBuffer& buffer, const std::vector<uint32_t>& slots, double radius_scale, SlotValues* filtered,
                    uint32_t* max_neighbours);
  float initial_radius(const VertexBuffer& b, size_t slot) const;  // r0 (sec. 2.2)

  ConsistentFilterSettings settings_;
  size_t pixels_;
  float r0_per_distance_;  // r0 / d for the K x K pixel solid angle
  size_t batch_bytes_;
  uint64_t paths_so_far_ = 0;
  ConsistentFilterStats stats_;
  // The pass in progress (its batches so far).
  uint32_t pass_max_neighbours_ = 0;
  uint64_t pass_vertices_ = 0;
  double batch_radius_scale_ = 0.0;  // r / r0 of the batch filtered last (0: none to query)
  // For agree_round: the statistics before the pass in progress or last filtered, its paths, and
  // what it reports (bit 0: filtering was on; bit 1: it had vertices; above: its largest ball count).
  bool in_pass_ = false;
  ConsistentFilterStats pass_start_stats_;
  uint64_t pass_paths_ = 0;
  uint64_t pass_report_ = 0;
  // Scratch, reused between batches.
  HashGrid grid_;
  std::vector<BatchVertex> batch_vertex_;  // per batch vertex
  GatherData gather_;                      // per grid record, in cell order: what eq. 1 reads
  std::vector<float> cell_radius_;
  std::vector<uint32_t> cell_begin_;                       // first record of each cell, then the end
  std::vector<std::pair<uint64_t, uint32_t>> cell_order_;  // (Morton code, cell), sorted
  std::vector<Rgb> in_, out_;
};

}  // namespace pathspace
