#include "pathspace/film/film.h"

#include <algorithm>
#include <cstring>
#include <string>

#include "pathspace/base/error.h"
#include "pathspace/parallel/parallel_for.h"

namespace pathspace {

Film::Film(int width, int height)
    : width_(width), height_(height), sum_(3 * size_t(width) * size_t(height)),
      sum_sq_(3 * size_t(width) * size_t(height)), count_(size_t(width) * size_t(height)) {}

namespace {
// Pixels per task of the per-pixel loops below (a film is read once per output: its frames' snapshots).
constexpr size_t kPixelGrain = size_t(1) << 14;
}  // namespace

Rgb Film::mean(size_t i) const {
  if (count_[i] == 0) return Rgb();
  const double n = count_[i];
  return Rgb(float(sum_[3 * i] / n), float(sum_[3 * i + 1] / n), float(sum_[3 * i + 2] / n));
}

Image Film::mean() const {
  Image img(width_, height_);
  parallel_for(count_.size(), kPixelGrain, [&](size_t begin, size_t end) {
    for (size_t i = begin; i < end; ++i) img.pixels[i] = mean(i);
  });
  return img;
}

Rgb Film::variance_of_mean(size_t i) const {
  Rgb v;
  const double n = count_[i];
  if (n < 2) return v;
  for (int c = 0; c < 3; ++c) {
    const double m = sum_[3 * i + c] / n;
    const double var = std::max(0.0, (sum_sq_[3 * i + c] - n * m * m) / (n - 1));
    v[c] = float(var / n);
  }
  return v;
}

Image Film::variance_of_mean() const {
  Image img(width_, height_);
  parallel_for(count_.size(), kPixelGrain, [&](size_t begin, size_t end) {
    for (size_t i = begin; i < end; ++i) img.pixels[i] = variance_of_mean(i);
  });
  return img;
}

void Film::clear() {
  std::fill(sum_.begin(), sum_.end(), 0.0);
  std::fill(sum_sq_.begin(), sum_sq_.end(), 0.0);
  std::fill(count_.begin(), count_.end(), 0u);
}

void Film::save_state(StateWriter& out) const {
  out.put("film.width", width_);
  out.put("film.height", height_);
  out.put_vector("film.sum", sum_);
  out.put_vector("film.sum_sq", sum_sq_);
  out.put_vector("film.count", count_);
}

void Film::load_state(StateReader& in) {
  int width = 0, height = 0;
  in.get("film.width", &width);
  in.get("film.height", &height);
  if (width != width_ || height != height_)
    throw Error("render state: film is " + std::to_string(width) + "x" + std::to_string(height) + ", this render is " +
                std::to_string(width_) + "x" + std::to_string(height_));
  in.get_vector("film.sum", &sum_, sum_.size());
  in.get_vector("film.sum_sq", &sum_sq_, sum_sq_.size());
  in.get_vector("film.count", &count_, count_.size());
}

namespace {
constexpr size_t kPixelBytes = 6 * sizeof(double) + sizeof(uint32_t);
}  // namespace

std::vector<uint8_t> Film::pixel_bytes(size_t begin, size_t end) const {
  const size_t n = end - begin;
  std::vector<uint8_t> out(n * kPixelBytes);
  uint8_t* p = out.data();
  std::memcpy(p, &sum_[3 * begin], 3 * n * sizeof(double));
  p += 3 * n * sizeof(double);
  std::memcpy(p, &sum_sq_[3 * begin], 3 * n * sizeof(double));
  p += 3 * n * sizeof(double);
  std::memcpy(p, &count_[begin], n * sizeof(uint32_t));
  return out;
}

void Film::set_pixel_bytes(size_t begin, size_t end, const std::vector<uint8_t>& bytes) {
  const size_t n = end - begin;
  if (end > count_.size() || bytes.size() != n * kPixelBytes) throw Error("film: a slice of the wrong size");
  const uint8_t* p = bytes.data();
  std::memcpy(&sum_[3 * begin], p, 3 * n * sizeof(double));
  p += 3 * n * sizeof(double);
  std::memcpy(&sum_sq_[3 * begin], p, 3 * n * sizeof(double));
  p += 3 * n * sizeof(double);
  std::memcpy(&count_[begin], p, n * sizeof(uint32_t));
}

}  // namespace pathspace
