// Host side of the splatting film: buffers, clearing, and the per-pass resolve into the Film.
#include "pathspace/film/splat_film.h"

#include <algorithm>

namespace pathspace {

SplatFilm::SplatFilm(int width, int height, double scale)
    : width_(width), height_(height), scale_(scale), sums_(3 * size_t(width) * size_t(height)),
      status_(kSplatStatusCount) {}

void SplatFilm::clear() {
  std::fill(sums_.begin(), sums_.end(), uint64_t(0));
  std::fill(status_.begin(), status_.end(), uint64_t(0));
}

SplatFilmView SplatFilm::view() {
  SplatFilmView v;
  v.sums = sums_.data();
  v.status = status_.data();
  v.width = width_;
  v.height = height_;
  v.scale = scale_;
  return v;
}

Rgb SplatFilm::value(uint32_t pixel) const {
  const uint64_t* s = &sums_[3 * size_t(pixel)];
  const double inv = 1.0 / scale_;
  return {float(double(s[0]) * inv), float(double(s[1]) * inv), float(double(s[2]) * inv)};
}

void SplatFilm::resolve_into(Film& film) const {
  const size_t n = pixel_count();
  for (size_t i = 0; i < n; ++i) film.add_sample(uint32_t(i), value(uint32_t(i)));
}

void SplatFilm::save_state(StateWriter& out, const std::string& key) const {
  out.put_vector(key + ".sums", sums_);
  out.put_vector(key + ".status", status_);
}

void SplatFilm::load_state(StateReader& in, const std::string& key) {
  in.get_vector(key + ".sums", &sums_, sums_.size());
  in.get_vector(key + ".status", &status_, status_.size());
}

void SplatFilm::hand_over(ProcessGroup& group) {
  group.all_sum(&sums_);
  group.all_sum(&status_);
  if (group.rank() != 0) clear();
}

}  // namespace pathspace
