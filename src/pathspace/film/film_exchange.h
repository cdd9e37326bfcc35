// The ordered reduction of a distributed render (docs/distributed.md). The film sums are doubles,
// whose addition is not associative, so passes cannot be summed per process and added up later:
// each rank owns a slice of the pixels, receives every pass of a round for its slice and adds them in
// pass order, exactly as one process adds its passes. At the end of a run the slices go to rank 0.
#pragma once

#include <cstddef>
#include <cstdint>

#include "pathspace/film/film.h"
#include "pathspace/parallel/process_group.h"

namespace pathspace {

class FilmExchange {
 public:
  FilmExchange(ProcessGroup& group, size_t pixels);

  // This rank's pixels [begin, end): contiguous, in rank order, sizes differing by at most one.
  size_t begin() const { return slice_begin(group_.rank()); }
  size_t end() const { return slice_begin(group_.rank() + 1); }

  // One round: rank r < passes rendered the round's r-th pass into its own pass_film (one sample per
  // pixel at most); the others' pass_film is ignored. Every rank adds the passes, in rank order, to
  // its slice of `film`. Throws on every rank when some pass put two samples into one pixel.
  void add_round(const Film& pass_film, int passes, Film* film);
  // Rank 0's film receives every rank's slice (the other ranks' films are unchanged).
  void gather(Film* film);

  uint64_t bytes_sent() const { return bytes_sent_; }

 private:
  size_t slice_begin(int rank) const { return pixels_ * size_t(rank) / size_t(group_.size()); }

  ProcessGroup& group_;
  size_t pixels_;
  uint64_t bytes_sent_ = 0;
};

}  // namespace pathspace
