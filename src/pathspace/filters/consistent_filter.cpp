#include "pathspace/filters/consistent_filter.h"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdint>

#include "pathspace/filters/vertex_buffer.h"
#include "pathspace/materials/bsdf_layers.h"
#include "pathspace/parallel/parallel_for.h"

namespace pathspace {

namespace {

size_t default_batch_bytes() {
  const long pages = ::sysconf(_SC_PHYS_PAGES), page = ::sysconf(_SC_PAGESIZE);
  const size_t physical = pages > 0 && page > 0 ? size_t(pages) * size_t(page) : size_t(8) << 30;
  return physical / 8;
}

bool finite(const Rgb& c) { return std::isfinite(c.r) && std::isfinite(c.g) && std::isfinite(c.b); }

// What the binary weights of sec. 2.1 (w_ij in {0, 1}) compare. Vertices of other layers or other
// places in their paths estimate other quantities and are never averaged (consistent_gather.h).
SimilarityKey similarity_key(const VertexBuffer& b, size_t i) {
  return {b.shading_normal[i], b.incident[i], b.throughput[i], b.visible_lights[i], b.open_distance[i], b.layer[i], b.selected[i]};
}

}  // namespace

ConsistentFilter::ConsistentFilter(const ConsistentFilterSettings& settings, const PerspectiveCamera& camera, size_t pixels)
    : settings_(settings),
      pixels_(std::max<size_t>(1, pixels)),
      // Solid angle of K x K pixels at the image centre, pi r0^2 / d^2 = K^2 A_pixel (sec. 2.2).
      r0_per_distance_(settings.radius_pixels * std::sqrt(camera.pixel_area() / kPi)),
      batch_bytes_(settings.batch_memory_mb > 0.0 ? size_t(settings.batch_memory_mb * 1048576.0) : default_batch_bytes()),
      grid_(HashGridConfig{}) {}

void ConsistentFilter::begin_frame(const PerspectiveCamera& camera) {
  r0_per_distance_ = settings_.radius_pixels * std::sqrt(camera.pixel_area() / kPi);
}

size_t ConsistentFilter::bytes_per_record() {
  // The grid's records (and their compacted copy) and slots, the slot index, each vertex's data in
  // batch order (weights' data, contribution, radius, and a copy of the radius for the median) and
  // in cell order (the gather's arrays, radius) and the two contribution arrays of the iteration.
  return 2 * sizeof(GridRecord) + 2 * sizeof(GridSlot) + sizeof(uint32_t) + sizeof(BatchVertex) + sizeof(float) +
         GatherData::bytes_per_record() + sizeof(float) + 2 * sizeof(Rgb);
}

FilterNeeds ConsistentFilter::needs() const {
  FilterNeeds n;
  n.visibility = (settings_.weights & kWeightVisibility) != 0;
  n.query_paths = settings_.aa_paths;
  n.caustics = settings_.caustics;
  return n;
}

size_t ConsistentFilter::batch_paths(int records_per_path) const {
  // Per path: its vertex buffer entry and filtered values, the filter's scratch per record, and the
  // same buffer again for the query-only paths (with their values and found flags).
  const size_t slots = size_t(std::max(1, records_per_path));
  size_t per_path = VertexBuffer::bytes_per_path() + slots * (VertexBuffer::bytes_per_slot() + sizeof(Rgb) + bytes_per_record());
  if (settings_.aa_paths > 0) per_path += VertexBuffer::bytes_per_path() + slots * (VertexBuffer::bytes_per_slot() + sizeof(Rgb) + 1);
  return std::max<size_t>(1, batch_bytes_ / per_path);
}

float ConsistentFilter::initial_radius(const VertexBuffer& b, size_t i) const {
  const float scale = b.layer[i] == kLayerMedium ? settings_.medium_radius_scale : 1.f;
  if (settings_.radius > 0.f) return settings_.radius * scale;
  return r0_per_distance_ * (b.prefix_distance[i] + length(b.position[i] - b.previous_position[i])) * scale;
}

void ConsistentFilter::filter(const VertexBuffer& buffer, uint64_t, uint32_t, SlotValues* filtered) {
  const auto start = std::chrono::steady_clock::now();
  if (!in_pass_) {
    in_pass_ = true;
    pass_start_stats_ = stats_;
    pass_paths_ = 0;
  }
  buffer.copy_contributions(filtered);  // every record keeps its own value unless averaged below
  const size_t paths = buffer.paths();
  uint32_t max_neighbours = 0;
  uint64_t vertices = 0;
  batch_radius_scale_ = 0.0;
  if (stats_.switched_off_after == 0) {
    const size_t per_batch = std::max<size_t>(1, batch_bytes_ / bytes_per_record());
    std::vector<uint32_t> slots;
    for (size_t p = 0; p < paths;) {
      // Whole paths, as many as fit (at least one).
      slots.clear();
      size_t q = p;
      for (; q < paths && (slots.empty() || slots.size() + buffer.count[q] <= per_batch); ++q)
        for (int r = 0; r < buffer.count[q]; ++r) slots.push_back(uint32_t(buffer.slot(q, r)));
      const double n = double(paths_so_far_ + q);  // paths so far, this batch included (eq. 2)
      const double scale = std::pow(double(pixels_) / n, double(settings_.alpha));
      filter_batch(buffer, slots, scale, filtered, &max_neighbours);
      batch_radius_scale_ = scale;
      ++stats_.batches;
      stats_.largest_batch = std::max<uint64_t>(stats_.largest_batch, slots.size());
      stats_.radius_scale_last = scale;
      vertices += slots.size();
      p = q;
    }
  } else {
    vertices = buffer.total_records();
  }
  paths_so_far_ += paths;
  pass_paths_ += paths;
  stats_.vertices += vertices;
  pass_vertices_ += vertices;
  pass_max_neighbours_ = std::max(pass_max_neighbours_, max_neighbours);
  stats_.filter_ms += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

void ConsistentFilter::end_pass() {
  ++stats_.passes;
  in_pass_ = false;
  pass_report_ = stats_.switched_off_after == 0 ? 1 | (pass_vertices_ > 0 ? 2 : 0) | uint64_t(pass_max_neighbours_) << 2 : 0;
  if (stats_.switched_off_after == 0) {
    stats_.max_neighbours_last = pass_max_neighbours_;
    // Sec. 2.2: no ball holds more than its own vertex, so averaging has ended.
    if (pass_vertices_ > 0 && pass_max_neighbours_ <= 1) stats_.switched_off_after = uint32_t(stats_.passes);
  }
  pass_max_neighbours_ = 0;
  pass_vertices_ = 0;
}

// The radius of the next pass depends on the paths filtered so far (eq. 2), wherever they were.
// Switching off (sec. 2.2) is agreed after each round (agree_round).
void ConsistentFilter::skip_pass(uint64_t paths) {
  paths_so_far_ += paths;
  ++stats_.passes;
}

// Replays end_pass's decision over the round's passes in pass order. All ranks began the round in
// the same state; a pass after the one that switched filtering off was filtered here but must not
// be: its statistics and paths are taken back and the session renders it again (at most once per
// rank and render).
bool ConsistentFilter::agree_round(const std::vector<uint64_t>& reports, int mine) {
  const size_t n = reports.size();
  for (size_t i = 0; i < n; ++i) {
    if ((reports[i] & 1) == 0) return false;  // filtering was off for the whole round already
    const uint32_t largest = uint32_t(reports[i] >> 2);
    stats_.max_neighbours_last = largest;
    stats_.switched_off_after = 0;
    if ((reports[i] & 2) == 0 || largest > 1) continue;
    // stats_.passes counts the whole round on every rank: pass i of the round is pass count passes - n + i + 1.
    stats_.switched_off_after = uint32_t(stats_.passes - n + i + 1);
    if (mine <= int(i)) return false;
    const ConsistentFilterStats agreed = stats_;
    stats_ = pass_start_stats_;
    stats_.passes = agreed.passes - 1;  // the render again counts it
    stats_.switched_off_after = agreed.switched_off_after;
    stats_.max_neighbours_last = agreed.max_neighbours_last;
    paths_so_far_ -= pass_paths_;
    pass_report_ = 0;
    return true;
  }
  return false;
}

void ConsistentFilter::query(const VertexBuffer& q, SlotValues* values, std::vector<uint8_t>* found) {
  const auto start = std::chrono::steady_clock::now();
  const size_t slots = q.paths() * size_t(q.records_per_path());
  values->assign(slots, Rgb());
  found->assign(slots, 0);
  const size_t linked = batch_radius_scale_ > 0.0 ? grid_.compacted_records() : 0;
  const SimilarityWeights weights(settings_);
  std::atomic<uint64_t> queries{0}, empty{0};
  parallel_for(q.paths(), 1024, [&](size_t begin, size_t end) {
    uint64_t local_queries = 0, local_empty = 0;
    CellRangeCache cache;
    for (size_t path = begin; path < end; ++path)
      for (int r = 0; r < q.count[path]; ++r) {
        const size_t i = q.slot(path, r);
        ++local_queries;
        const float radius = float(double(initial_radius(q, i)) * batch_radius_scale_);
        if (!linked || !all_finite(q.position[i]) || !(radius > 0.f) || !std::isfinite(radius)) {
          ++local_empty;
          continue;
        }
        // Eq. 1 around a point that is not one of the data points (fig. 5): no central contribution.
        const GatherSum sum = gather_.gather(grid_, GatherQuery{q.position[i], radius, similarity_key(q, i)}, weights, &cache);
        if (sum.count == 0) {
          ++local_empty;
          continue;
        }
        (*values)[i] = sum.mean();
        (*found)[i] = 1;
      }
    queries += local_queries;
    empty += local_empty;
  });
  stats_.queries += queries.load();
  stats_.empty_queries += empty.load();
  stats_.filter_ms += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

void ConsistentFilter::filter_batch(const VertexBuffer& b, const std::vector<uint32_t>& slots, double radius_scale,
                                    SlotValues* filtered, uint32_t* max_neighbours) {
  const size_t m = slots.size();
  if (m == 0) return;
  // Each vertex's radius and what the weights compare, gathered in batch order (the buffer's arrays
  // read front to back). Radius 0: no usable position or radius, left out of the grid.
  batch_vertex_.resize(m);
  parallel_for(m, 4096, [&](size_t begin, size_t end) {
    for (size_t k = begin; k < end; ++k) {
      const size_t i = slots[k];
      const float r = float(double(initial_radius(b, i)) * radius_scale);
      const bool usable = all_finite(b.position[i]) && std::isfinite(r) && r > 0.f;
      batch_vertex_[k] = {similarity_key(b, i), b.contribution[i], usable ? r : 0.f};
    }
  });
  std::vector<float> valid_radii;
  valid_radii.reserve(m);
  for (const BatchVertex& v : batch_vertex_)
    if (v.radius > 0.f) valid_radii.push_back(v.radius);
  if (valid_radii.empty()) return;
  // Cells for the median radius: most queries visit 8 cells; larger balls visit more, still exactly.
  std::nth_element(valid_radii.begin(), valid_radii.begin() + ptrdiff_t(valid_radii.size() / 2), valid_radii.end());
  const float cell_radius = valid_radii[valid_radii.size() / 2];
  const Vec3 nowhere(std::nanf(""), 0.f, 0.f);  // not linked: never found by a query
  grid_.build(m, cell_radius, [&](size_t k) { return batch_vertex_[k].radius > 0.f ? b.position[slots[k]] : nowhere; });

  // Work in the grid's cell order (record c of the compacted grid is batch vertex base[c].payload):
  // the weights' data and contributions are stored in that order (one random read per vertex to
  // permute them), so a query reads each cell's data from a few consecutive cache lines; queries go
  // cell by cell, the cells in Morton order, so consecutive queries share their neighbouring cells.
  // At 1920x1080 this made second-bounce vertices 2.3x faster than queries in image order, primary
  // hits 10% slower (docs/benchmarks.md).
  const size_t linked = grid_.compacted_records();
  const GridRecord* base = linked ? &grid_.record(0) : nullptr;
  gather_.resize(linked);
  cell_radius_.resize(linked);
  in_.resize(linked);
  out_.resize(linked);
  parallel_for(linked, 4096, [&](size_t begin, size_t end) {
    for (size_t c = begin; c < end; ++c) {
      const BatchVertex& v = batch_vertex_[base[c].payload];
      gather_.set(c, base[c].position, v.key);
      cell_radius_[c] = v.radius;
      in_[c] = v.contribution;
    }
  });
  // Query order: cell by cell (the records of a cell are contiguous), the cells in Morton order of
  // their coordinates, so consecutive queries share most of their neighbouring cells.
  cell_begin_.clear();
  for (size_t c = 0; c < linked; ++c)
    if (c == 0 || base[c - 1].next == kNoRecord) cell_begin_.push_back(uint32_t(c));
  const size_t cells = cell_begin_.size();
  cell_order_.resize(cells);
  parallel_for(cells, 4096, [&](size_t begin, size_t end) {
    for (size_t q = begin; q < end; ++q) {
      const CellCoord cc = grid_.geometry().cell_of(base[cell_begin_[q]].position);
      cell_order_[q] = {morton_cell_order(cc), uint32_t(q)};
    }
  });
  std::sort(cell_order_.begin(), cell_order_.end());
  cell_begin_.push_back(uint32_t(linked));
  const SimilarityWeights weights(settings_);
  std::atomic<uint32_t> largest{0};
  std::atomic<uint64_t> averaged{0};
  const int iterations = std::max(1, settings_.iterations);
  for (int iteration = 0; iteration < iterations; ++iteration) {
    // After the last iteration, what the query-only paths average: the buffer in_ swaps into out_,
    // which is left alone until the next batch sets its values.
    gather_.set_values(in_);
    parallel_for(cells, 64, [&](size_t begin, size_t end) {
      uint32_t local_largest = 0;
      uint64_t local_averaged = 0;
      CellRangeCache cache;
      for (size_t q = begin; q < end; ++q)
      for (size_t c = cell_begin_[cell_order_[q].second], last = cell_begin_[cell_order_[q].second + 1]; c < last; ++c) {
        if (!finite(in_[c])) {
          out_[c] = in_[c];
          continue;
        }
        // Eq. 1 with binary weights: the mean over the similar vertices in the ball, x_i included.
        const GatherSum sum = gather_.gather(grid_, GatherQuery{gather_.position(c), cell_radius_[c], gather_.key(c)}, weights, &cache);
        if (sum.count == 0) {  // not even itself (a degenerate vertex): keep its own value
          out_[c] = in_[c];
          continue;
        }
        out_[c] = sum.mean();
        local_largest = std::max(local_largest, sum.count);
        local_averaged += sum.count;
      }
      uint32_t seen = largest.load();
      while (local_largest > seen && !largest.compare_exchange_weak(seen, local_largest)) {}
      averaged += local_averaged;
    });
    in_.swap(out_);  // fig. 2: the next iteration averages the averages
  }
  // Vertices left out of the grid (no usable position or radius, probe failure) keep their own value.
  for (size_t c = 0; c < linked; ++c) (*filtered)[slots[base[c].payload]] = in_[c];
  *max_neighbours = std::max(*max_neighbours, largest.load());
  stats_.averaged += averaged.load();
}

void ConsistentFilter::statistics(Statistics& out) const {
  out.counter("consistent.passes", stats_.passes);
  out.counter("consistent.batches", stats_.batches, "batches filtered (each averages over itself only)");
  out.counter("consistent.vertices", stats_.vertices);
  out.counter("consistent.paths", paths_so_far_, "n of eq. 2: paths so far, over all passes and resumed runs");
  out.counter("consistent.largest_batch", stats_.largest_batch, "records in the largest batch");
  out.bytes("consistent.batch_memory", batch_bytes_, "memory budget of one batch (--psf-batch-memory)");
  out.value("consistent.radius_scale", stats_.radius_scale_last, "r(n) / r0 in the last batch (eq. 2)");
  out.value("consistent.mean_neighbours", stats_.vertices ? double(stats_.averaged) / double(stats_.vertices) : 0.0,
             "contributions averaged per vertex and iteration");
  out.counter("consistent.max_neighbours_last", stats_.max_neighbours_last, "largest ball count in the last filtered pass");
  out.counter("consistent.query_paths_records", stats_.queries, "records of the query-only anti-aliasing paths (--psf-aa-paths)");
  out.counter("consistent.empty_queries", stats_.empty_queries, "query records with no similar vertex in their ball (not accumulated)");
  out.counter("consistent.switched_off_after", stats_.switched_off_after,
              "passes after which every ball held only its own vertex and filtering stopped (0: still filtering; sec. 2.2)");
  out.seconds("consistent.filter_time", stats_.filter_ms * 1e-3);
  out.value("consistent.filter_ns_per_vertex", stats_.vertices ? stats_.filter_ms * 1e6 / double(stats_.vertices) : 0.0);
}

void ConsistentFilter::save_state(StateWriter& out) const {
  out.put("consistent.paths", paths_so_far_);
  out.put("consistent.stats", stats_);
}

void ConsistentFilter::load_state(StateReader& in) {
  in.get("consistent.paths", &paths_so_far_);
  in.get("consistent.stats", &stats_);
}

}  // namespace pathspace
