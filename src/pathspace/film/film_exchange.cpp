#include "pathspace/film/film_exchange.h"

#include <atomic>
#include <cstring>
#include <vector>

#include "pathspace/base/error.h"
#include "pathspace/parallel/parallel_for.h"

namespace pathspace {

namespace {

// A pass's slice on the wire: a status byte, then per pixel whether it has its sample, then the
// samples as floats. A float is the sample exactly (Film::sum of a one-pass film), 13 bytes a pixel.
constexpr uint8_t kOk = 0, kSeveralSamples = 1;
constexpr size_t kValueBytes = 3 * sizeof(float);
constexpr size_t kGrain = 4096;

std::vector<uint8_t> pack(const Film& pass, size_t begin, size_t end) {
  const size_t n = end - begin;
  std::vector<uint8_t> out(1 + n + n * kValueBytes, 0);
  uint8_t* has = out.data() + 1;
  uint8_t* values = has + n;
  std::atomic<bool> several{false};
  parallel_for(n, kGrain, [&](size_t first, size_t last) {
    for (size_t i = first; i < last; ++i) {
      const uint32_t count = pass.samples(uint32_t(begin + i));
      if (count > 1) several = true;
      if (count != 1) continue;
      has[i] = 1;
      const Rgb v = pass.sum(uint32_t(begin + i));
      const float c[3] = {v.r, v.g, v.b};
      std::memcpy(values + i * kValueBytes, c, kValueBytes);
    }
  });
  if (several) out[0] = kSeveralSamples;
  return out;
}

}  // namespace

FilmExchange::FilmExchange(ProcessGroup& group, size_t pixels) : group_(group), pixels_(pixels) {}

void FilmExchange::add_round(const Film& pass_film, int passes, Film* film) {
  const int ranks = group_.size();
  std::vector<std::vector<uint8_t>> send(static_cast<size_t>(ranks)), received;
  if (group_.rank() < passes)
    for (int d = 0; d < ranks; ++d) {
      send[size_t(d)] = pack(pass_film, slice_begin(d), slice_begin(d + 1));
      bytes_sent_ += send[size_t(d)].size();
    }
  group_.all_to_all(send, &received);
  // Every rank sees every sender's status, so all of them throw together and nobody waits.
  for (int s = 0; s < passes; ++s)
    if (received[size_t(s)].empty() || received[size_t(s)][0] != kOk)
      throw Error("distributed rendering: a pass added several samples to one pixel (rank " + std::to_string(s) +
                  "), which the ordered reduction cannot reproduce; render this configuration in one process");
  const size_t b = begin(), n = end() - begin();
  for (int s = 0; s < passes; ++s)
    if (received[size_t(s)].size() != 1 + n + n * kValueBytes) throw Error("distributed rendering: a pass slice of the wrong size");
  // Pixels in parallel, each pixel's passes in pass order: the single process's sums, bit for bit.
  parallel_for(n, kGrain, [&](size_t first, size_t last) {
    for (int s = 0; s < passes; ++s) {
      const uint8_t* has = received[size_t(s)].data() + 1;
      const uint8_t* values = has + n;
      for (size_t i = first; i < last; ++i) {
        if (!has[i]) continue;
        float c[3];
        std::memcpy(c, values + i * kValueBytes, kValueBytes);
        film->add_sample(uint32_t(b + i), Rgb(c[0], c[1], c[2]));
      }
    }
  });
}

void FilmExchange::gather(Film* film) {
  const std::vector<uint8_t> mine = film->pixel_bytes(begin(), end());
  if (group_.rank() != 0) bytes_sent_ += mine.size();
  const std::vector<std::vector<uint8_t>> slices = group_.gather(mine);
  if (group_.rank() != 0) return;
  for (int r = 1; r < group_.size(); ++r) film->set_pixel_bytes(slice_begin(r), slice_begin(r + 1), slices[size_t(r)]);
}

}  // namespace pathspace
