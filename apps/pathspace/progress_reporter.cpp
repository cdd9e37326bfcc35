#include "progress_reporter.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <string>

#include <fmt/format.h>

namespace pathspace::cli {

namespace {

std::string format_duration(double seconds) {
  const auto s = static_cast<long>(std::max(0.0, seconds) + 0.5);
  if (s >= 3600) return fmt::format("{}:{:02}:{:02}", s / 3600, s / 60 % 60, s % 60);
  return fmt::format("{}:{:02}", s / 60, s % 60);
}

}  // namespace

ProgressReporter::ProgressReporter(std::FILE* out, uint64_t pixels, bool quiet)
    : out_(out), pixels_(pixels), quiet_(quiet), tty_(::isatty(::fileno(out)) != 0) {}

ProgressReporter::~ProgressReporter() { finish(); }

void ProgressReporter::watch(const RenderSession& session) {
  if (quiet_ || watcher_.joinable()) return;
  stop_ = false;
  watcher_ = std::thread([this, &session] { tick(session); });
}

void ProgressReporter::tick(const RenderSession& session) {
  std::unique_lock<std::mutex> lock(mutex_);
  while (!wake_.wait_for(lock, std::chrono::seconds(1), [this] { return stop_; })) {
    const PassProgress p = session.pass_progress();
    if (p.running && p.seconds >= kInPassAfterSeconds) in_pass(p);
  }
}

void ProgressReporter::in_pass(const PassProgress& p) {
  const std::string text = fmt::format("pass {}: {:.0f}% of its work so far, {} in the pass", p.pass, 100.0 * p.fraction,
                                       format_duration(p.seconds));
  if (tty_) {
    emit("\r" + text + "\x1b[K");
    drew_ = true;
  } else {
    emit(text + "\n");
  }
}

// A progress line that cannot be written (a closed pipe: `render ... 2>&1 | head -1`; SIGPIPE is
// ignored, cli_app.cpp) mutes the reporter: the render goes on and writes its outputs.
void ProgressReporter::emit(const std::string& text) {
  if (quiet_) return;
  if (std::fputs(text.c_str(), out_) < 0 || std::fflush(out_) != 0) quiet_ = true;
}

void ProgressReporter::update(const RenderProgress& p) {
  if (quiet_) return;
  const std::lock_guard<std::mutex> lock(mutex_);
  const double percent = 100.0 * p.fraction;
  const double samples_per_s = p.elapsed_s > 0 ? double(p.passes_done) * double(pixels_) / p.elapsed_s : 0.0;
  const double mrays_per_s = p.elapsed_s > 0 ? double(p.rays) / p.elapsed_s * 1e-6 : 0.0;
  const double eta = p.fraction > 0 ? p.elapsed_s * (1.0 - p.fraction) / p.fraction : 0.0;
  const std::string numbers =
      fmt::format("{:5.1f}%  {} elapsed, ETA {}  {:.3g} Msamples/s  {:.1f} Mrays/s  ({} spp)", percent,
                  format_duration(p.elapsed_s), format_duration(eta), samples_per_s * 1e-6, mrays_per_s,
                  p.session_passes);
  if (tty_) {
    constexpr int kBarWidth = 30;
    const int filled = std::clamp(static_cast<int>(p.fraction * kBarWidth + 0.5), 0, kBarWidth);
    emit(fmt::format("\r[{}{}] {}\x1b[K", std::string(size_t(filled), '#'), std::string(size_t(kBarWidth - filled), '.'), numbers));
    drew_ = true;
  } else if (percent + 1e-9 >= next_plain_percent_) {
    emit(numbers + "\n");
    while (next_plain_percent_ <= percent + 1e-9) next_plain_percent_ += 25;
  }
}

void ProgressReporter::finish() {
  if (watcher_.joinable()) {
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      stop_ = true;
    }
    wake_.notify_all();
    watcher_.join();
  }
  if (quiet_ || !drew_) return;
  emit("\n");
  drew_ = false;
}

}  // namespace pathspace::cli
