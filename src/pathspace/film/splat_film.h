// Splatting film for light paths (LT, and later BPT t = 1 / PCLT projection): many threads add
// contributions to arbitrary pixels. Sums are 64-bit fixed point updated with integer atomics,
// because integer addition is associative: the result is bit-identical for every thread count and
// schedule (docs/architecture.md §5), which float atomics are not. Each contribution is quantised
// on its own (round to nearest multiple of 1/scale), so quantisation never depends on order.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "pathspace/base/state_archive.h"
#include "pathspace/film/film.h"
#include "pathspace/parallel/process_group.h"
#include "pathspace/math/rgb.h"
#include "pathspace/parallel/atomics.h"

namespace pathspace {

// Counters of contributions that could not be represented (index into SplatFilmView::status).
enum SplatStatus : uint32_t { kSplatOverflow = 0, kSplatNonFinite = 1, kSplatStatusCount = 2 };

// Device-safe view: raw pointers into SplatFilm's buffers.
struct SplatFilmView {
  uint64_t* sums = nullptr;    // 3 fixed-point channels per pixel
  uint64_t* status = nullptr;  // kSplatStatusCount counters
  int width = 0, height = 0;
  double scale = 0.0;          // fixed-point units per unit of pixel value
  // True when `sums` is one CPU worker's own shard (SplatFilm::worker_view): plain adds, no atomics.
  bool exclusive = false;

  // Largest single contribution accepted, in units: leaves head room so that sums of many large
  // values in one pixel do not wrap before a pass ends.
  static constexpr double kMaxUnits = 4.0e18;  // ~2^61.8

  // Starts loading a pixel's sums into the cache ahead of add(): splats land on random pixels, and the
  // load missed the cache on most of them (LT, BPT). Call it before the connection's shadow ray.
  PS_HD void prefetch(uint32_t pixel) const {
#if !defined(__CUDA_ARCH__)
    const uint64_t* s = sums + 3 * size_t(pixel);
    __builtin_prefetch(s, 1, 3);
    __builtin_prefetch(s + 2, 1, 3);  // the 24 bytes may straddle two cache lines
#else
    (void)pixel;
#endif
  }

  // Adds v (already in pixel-value units, i.e. divided by the number of light paths) to a pixel.
  PS_HD void add(uint32_t pixel, const Rgb& v) const {
    if (!all_finite(v)) {
      atomic_fetch_add(&status[kSplatNonFinite], uint64_t(1));
      return;
    }
    uint64_t q[3];
    for (int c = 0; c < 3; ++c) {
      const double units = double(v[c]) * scale + 0.5;
      if (!(units < kMaxUnits) || v[c] < 0.f) {  // negative values cannot occur for physical BSDFs
        atomic_fetch_add(&status[kSplatOverflow], uint64_t(1));
        return;
      }
      q[c] = uint64_t(units);
    }
    uint64_t* s = sums + 3 * size_t(pixel);
    for (int c = 0; c < 3; ++c) {
      if (q[c] == 0) continue;
      const uint64_t old = exclusive ? s[c] : atomic_fetch_add(&s[c], q[c]);
      if (exclusive) s[c] = old + q[c];
      if (old + q[c] < old) atomic_fetch_add(&status[kSplatOverflow], uint64_t(1));  // wrapped
    }
  }
};

class SplatFilm {
 public:
  // 2^32 units per unit of pixel value: resolution 2.3e-10 per contribution, up to 4.3e9 per pixel
  // and pass (ample for radiance-scaled scenes; raise or lower --lt-splat-scale for extreme ones).
  static constexpr double kDefaultScale = 4294967296.0;

  SplatFilm(int width, int height, double scale = kDefaultScale);

  int width() const { return width_; }
  int height() const { return height_; }
  size_t pixel_count() const { return size_t(width_) * size_t(height_); }
  double scale() const { return scale_; }

  void clear();
  // The view every thread may add to at once (atomic adds): the GPU's, and the fallback.
  SplatFilmView view();
  // The view for the calling CPU worker thread (inside parallel_for): its own shard of the sums,
  // added to without atomics, which cost a locked read-modify-write per channel of every splat
  // (LT and BPT spent 9-12% of a pass there). Shards take at most kMaxShardBytes together; a worker
  // beyond that gets view(). merge_workers() must run after the parallel loop, before the sums are
  // read: the sums are integers, so the image is the same bits either way.
  SplatFilmView worker_view();
  // Adds every shard into the sums and zeroes the shards (single-threaded caller, after the loop).
  // A sum that wraps here counts as an overflow, as it would have in an atomic add.
  void merge_workers();
  static constexpr size_t kMaxShardBytes = size_t(256) << 20;
  // Value of pixel i (sum of contributions) as the film sees it.
  Rgb value(uint32_t pixel) const;
  // Adds every pixel's value as one sample to `film` (a light-tracing pass = one sample per pixel).
  void resolve_into(Film& film) const;
  uint64_t overflows() const { return status_[kSplatOverflow]; }
  uint64_t non_finite() const { return status_[kSplatNonFinite]; }
  // Sums and status as sections "<key>.sums" and "<key>.status" (sizes must match when loading).
  void save_state(StateWriter& out, const std::string& key) const;
  void load_state(StateReader& in, const std::string& key);
  // A distributed render (docs/distributed.md): rank 0 receives the sums of every rank (fixed point,
  // so in any order) and the other ranks start again from zero, so handing over twice counts once.
  void hand_over(ProcessGroup& group);

 private:
  int width_, height_;
  double scale_;
  std::vector<uint64_t> sums_;
  std::vector<uint64_t> status_;
  // One shard per worker slot (parallel/worker_slot.h) below the memory cap, created by that worker
  // on first use: a slot's shard is only touched by the thread holding the slot, so no lock.
  std::vector<std::unique_ptr<std::vector<uint64_t>>> shards_;
  std::vector<uint8_t> shard_used_;  // per slot: added to since the last merge
};

}  // namespace pathspace
