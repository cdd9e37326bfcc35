// Host side of the splatting film: buffers, clearing, and the per-pass resolve into the Film.
#include "pathspace/film/splat_film.h"

#include <algorithm>

#include "pathspace/parallel/parallel_for.h"
#include "pathspace/parallel/worker_slot.h"

namespace pathspace {

SplatFilm::SplatFilm(int width, int height, double scale)
    : width_(width), height_(height), scale_(scale), sums_(3 * size_t(width) * size_t(height)),
      status_(kSplatStatusCount) {
  const size_t shard_bytes = std::max<size_t>(sums_.size() * sizeof(uint64_t), 1);
  const size_t slots = std::min<size_t>(size_t(std::max(worker_slot_count(), 0)), kMaxShardBytes / shard_bytes);
  shards_.resize(slots);
  shard_used_.assign(slots, 0);
}

void SplatFilm::clear() {
  std::fill(sums_.begin(), sums_.end(), uint64_t(0));
  std::fill(status_.begin(), status_.end(), uint64_t(0));
  for (size_t i = 0; i < shards_.size(); ++i)
    if (shard_used_[i]) {  // a pass that ended without merge_workers (an exception)
      std::fill(shards_[i]->begin(), shards_[i]->end(), uint64_t(0));
      shard_used_[i] = 0;
    }
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

SplatFilmView SplatFilm::worker_view() {
  SplatFilmView v = view();
  const int slot = worker_slot();
  if (slot < 0 || size_t(slot) >= shards_.size()) return v;
  std::unique_ptr<std::vector<uint64_t>>& shard = shards_[size_t(slot)];
  if (!shard) shard = std::make_unique<std::vector<uint64_t>>(sums_.size(), uint64_t(0));
  shard_used_[size_t(slot)] = 1;
  v.sums = shard->data();
  v.exclusive = true;
  return v;
}

void SplatFilm::merge_workers() {
  std::vector<uint64_t*> used;
  for (size_t i = 0; i < shards_.size(); ++i)
    if (shard_used_[i]) {
      used.push_back(shards_[i]->data());
      shard_used_[i] = 0;
    }
  if (used.empty()) return;
  std::atomic<uint64_t> wrapped{0};
  parallel_for(sums_.size(), 1 << 14, [&](size_t begin, size_t end) {
    uint64_t local_wrapped = 0;
    for (uint64_t* shard : used)
      for (size_t i = begin; i < end; ++i) {
        const uint64_t sum = sums_[i] + shard[i];
        local_wrapped += sum < sums_[i];
        sums_[i] = sum;
        shard[i] = 0;
      }
    wrapped += local_wrapped;
  });
  status_[kSplatOverflow] += wrapped;
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
