// Film: per-pixel accumulation of path samples with first and second moments, so every render yields
// a mean image and a variance-of-the-mean image (used by the z-tests, docs/testing.md).
// Each pixel is written by exactly one thread per pass, in sample order, so sums are deterministic.
#pragma once

#include <cstdint>
#include <vector>

#include "pathspace/base/state_archive.h"
#include "pathspace/film/image.h"

namespace pathspace {

class Film {
 public:
  Film(int width, int height);

  int width() const { return width_; }
  int height() const { return height_; }
  size_t pixel_count() const { return count_.size(); }

  // Adds one sample (the pixel estimate of one camera path). Not synchronised: a pixel must be owned
  // by one thread at a time.
  void add_sample(uint32_t pixel, const Rgb& value) {
    double* s = &sum_[3 * size_t(pixel)];
    double* q = &sum_sq_[3 * size_t(pixel)];
    for (int c = 0; c < 3; ++c) {
      s[c] += value[c];
      q[c] += double(value[c]) * double(value[c]);
    }
    ++count_[pixel];
  }

  uint32_t samples(uint32_t pixel) const { return count_[pixel]; }
  // The sum of a pixel's samples. A film of one pass holds each pixel's one sample here exactly
  // (0 + v), which is how a distributed render ships a pass (film_exchange.h).
  Rgb sum(uint32_t pixel) const {
    const double* s = &sum_[3 * size_t(pixel)];
    return Rgb(float(s[0]), float(s[1]), float(s[2]));
  }
  // Mean per pixel (black where no samples).
  Image mean() const;
  Rgb mean(size_t pixel) const;
  // Unbiased estimate of the variance of the pixel mean: s^2 / n (0 below two samples).
  Image variance_of_mean() const;
  Rgb variance_of_mean(size_t pixel) const;
  void clear();
  // The per-pixel sums, sums of squares and counts (a restored film continues bit for bit).
  void save_state(StateWriter& out) const;
  void load_state(StateReader& in);
  // Pixels [begin, end) as raw bytes (sums, squares, counts) and back: the slices of a distributed
  // render are gathered onto rank 0 with these (film_exchange.h).
  std::vector<uint8_t> pixel_bytes(size_t begin, size_t end) const;
  void set_pixel_bytes(size_t begin, size_t end, const std::vector<uint8_t>& bytes);

 private:
  int width_, height_;
  std::vector<double> sum_, sum_sq_;
  std::vector<uint32_t> count_;
};

}  // namespace pathspace
