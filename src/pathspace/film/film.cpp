#include "pathspace/film/film.h"

#include <algorithm>

namespace pathspace {

Film::Film(int width, int height)
    : width_(width), height_(height), sum_(3 * size_t(width) * size_t(height)),
      sum_sq_(3 * size_t(width) * size_t(height)), count_(size_t(width) * size_t(height)) {}

Image Film::mean() const {
  Image img(width_, height_);
  for (size_t i = 0; i < count_.size(); ++i) {
    if (count_[i] == 0) continue;
    const double n = count_[i];
    img.pixels[i] = Rgb(float(sum_[3 * i] / n), float(sum_[3 * i + 1] / n), float(sum_[3 * i + 2] / n));
  }
  return img;
}

Image Film::variance_of_mean() const {
  Image img(width_, height_);
  for (size_t i = 0; i < count_.size(); ++i) {
    const double n = count_[i];
    if (n < 2) continue;
    for (int c = 0; c < 3; ++c) {
      const double m = sum_[3 * i + c] / n;
      const double var = std::max(0.0, (sum_sq_[3 * i + c] - n * m * m) / (n - 1));
      img.pixels[i][c] = float(var / n);
    }
  }
  return img;
}

void Film::clear() {
  std::fill(sum_.begin(), sum_.end(), 0.0);
  std::fill(sum_sq_.begin(), sum_sq_.end(), 0.0);
  std::fill(count_.begin(), count_.end(), 0u);
}

}  // namespace pathspace
