// Progress output of `pathspace render`: a redrawn one-line bar (percent, elapsed, ETA, samples/s,
// Mrays/s) when stdout is a terminal, and a few plain lines otherwise (logs, CI). A pass that runs
// longer than 2 s also reports from inside, once a second (watch()): its number, how much of its
// work is done and how long it has run, so a huge single pass is never silent.
#pragma once

#include <condition_variable>
#include <cstdint>
#include <cstdio>
#include <mutex>
#include <string>
#include <thread>

#include "pathspace/session/render_session.h"

namespace pathspace::cli {

class ProgressReporter {
 public:
  // pixels: samples per pass. quiet: print nothing.
  ProgressReporter(std::FILE* out, uint64_t pixels, bool quiet);
  ~ProgressReporter();
  ProgressReporter(const ProgressReporter&) = delete;
  ProgressReporter& operator=(const ProgressReporter&) = delete;
  // After each pass (the render thread).
  void update(const RenderProgress& p);
  // Starts reporting from inside long passes of `session`, until finish().
  void watch(const RenderSession& session);
  // Stops watching and ends the bar's line.
  void finish();

  static constexpr double kInPassAfterSeconds = 2.0;  // a pass reports from inside once this old

 private:
  void in_pass(const PassProgress& p);
  void emit(const std::string& text);
  void tick(const RenderSession& session);

  std::mutex mutex_;  // update() and the watcher print in turn
  std::condition_variable wake_;
  bool stop_ = false;
  std::thread watcher_;
  std::FILE* out_;
  uint64_t pixels_;
  bool quiet_, tty_;
  int next_plain_percent_ = 25;
  bool drew_ = false;
};

}  // namespace pathspace::cli
