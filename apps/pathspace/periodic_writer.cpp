#include "periodic_writer.h"

#include <cstdio>
#include <exception>
#include <utility>

#include <fmt/format.h>

namespace pathspace::cli {

namespace {

void warn(const char* what, const std::exception& e) { fmt::print(stderr, "pathspace render: warning: {}: {}\n", what, e.what()); }

}  // namespace

PeriodicWriter::PeriodicWriter(const OutputPlan& plan, double output_every, std::string checkpoint_path, double checkpoint_every,
                               std::function<CheckpointInfo(const RenderSession&)> checkpoint_info)
    : plan_(plan),
      output_every_(output_every),
      checkpoint_every_(checkpoint_every),
      checkpoint_path_(std::move(checkpoint_path)),
      checkpoint_info_(std::move(checkpoint_info)) {}

bool PeriodicWriter::due(Clock::time_point* last, double every) {
  if (every <= 0.0 || std::chrono::duration<double>(Clock::now() - *last).count() < every) return false;
  *last = Clock::now();
  return true;
}

void PeriodicWriter::after_pass(RenderSession& session, bool gathered) {
  if (session.distributed() && !gathered) {
    if (output_pending_ || checkpoint_pending_) return;  // asked already
    output_pending_ = due(&last_output_, output_every_) && !output_job_.busy();
    checkpoint_pending_ = due(&last_checkpoint_, checkpoint_every_) && !checkpoint_job_.busy();
    if (output_pending_ || checkpoint_pending_) session.request_gather();
    return;
  }
  const bool output = session.distributed() ? std::exchange(output_pending_, false) : due(&last_output_, output_every_);
  const bool checkpoint = session.distributed() ? std::exchange(checkpoint_pending_, false) : due(&last_checkpoint_, checkpoint_every_);
  if (output && !output_job_.busy())
    output_job_.start([this, snap = session.snapshot()] {
      try {
        write_outputs(plan_, snap, OutputKind::periodic);
      } catch (const std::exception& e) {
        warn("periodic output write failed", e);
      }
    });
  if (checkpoint && !checkpoint_job_.busy())
    checkpoint_job_.start([this, info = checkpoint_info_(session), state = session.save_state()] {
      try {
        write_checkpoint(checkpoint_path_, info, state);
      } catch (const std::exception& e) {
        warn("periodic checkpoint failed", e);
      }
    });
}

void PeriodicWriter::finish() {
  output_job_.wait();
  checkpoint_job_.wait();
}

std::string PeriodicWriter::summary() const {
  if (!output_job_.jobs_done() && !checkpoint_job_.jobs_done()) return {};
  return fmt::format("periodic writes: {} output sets, {} checkpoints, {:.2f} s of CPU on a background thread\n", output_job_.jobs_done(),
                     checkpoint_job_.jobs_done(), output_job_.cpu_seconds() + checkpoint_job_.cpu_seconds());
}

}  // namespace pathspace::cli
