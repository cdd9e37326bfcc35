// PeriodicWriter: `render --write-every S` and `--checkpoint-every S`. Called after every pass, it
// takes a snapshot (or the session's state) on the render thread when a write is due and hands the
// encoding and writing to a background job (parallel/background_job.h). A write still running when
// the next is due is skipped, so the render never waits for the disk; a failed write is a warning.
// In a distributed render rank 0's clock decides: a due write asks the ranks to gather the film at
// the next round boundary (RenderSession::request_gather) and is taken when it has been gathered.
#pragma once

#include <chrono>
#include <functional>
#include <string>

#include "pathspace/checkpoint/checkpoint_file.h"
#include "pathspace/parallel/background_job.h"
#include "pathspace/session/render_session.h"
#include "render_outputs.h"

namespace pathspace::cli {

class PeriodicWriter {
 public:
  // `plan` and `checkpoint_info` must outlive the writer; seconds <= 0 turns that kind off.
  PeriodicWriter(const OutputPlan& plan, double output_every, std::string checkpoint_path, double checkpoint_every,
                 std::function<CheckpointInfo(const RenderSession&)> checkpoint_info);
  // After a pass or round (on the render thread, between passes); `gathered`: RenderProgress::gathered.
  void after_pass(RenderSession& session, bool gathered = false);
  // Waits for the writes in flight.
  void finish();
  // "periodic writes: ..." for the summary; empty when nothing was written.
  std::string summary() const;

 private:
  using Clock = std::chrono::steady_clock;
  static bool due(Clock::time_point* last, double every);

  const OutputPlan& plan_;
  double output_every_, checkpoint_every_;
  std::string checkpoint_path_;
  std::function<CheckpointInfo(const RenderSession&)> checkpoint_info_;
  Clock::time_point last_output_ = Clock::now(), last_checkpoint_ = Clock::now();
  BackgroundJob output_job_, checkpoint_job_;
  bool output_pending_ = false, checkpoint_pending_ = false;  // due, waiting for the gathered film
};

}  // namespace pathspace::cli
