// Progress output of `pathspace render`: a redrawn one-line bar (percent, elapsed, ETA, samples/s,
// Mrays/s) when stdout is a terminal, and a few plain lines otherwise (logs, CI).
#pragma once

#include <cstdint>
#include <cstdio>

#include "pathspace/session/render_session.h"

namespace pathspace::cli {

class ProgressReporter {
 public:
  // pixels: samples per pass. quiet: print nothing.
  ProgressReporter(std::FILE* out, uint64_t pixels, bool quiet);
  void update(const RenderProgress& p);
  // Ends the bar's line.
  void finish();

 private:
  std::FILE* out_;
  uint64_t pixels_;
  bool quiet_, tty_;
  int next_plain_percent_ = 25;
  bool drew_ = false;
};

}  // namespace pathspace::cli
