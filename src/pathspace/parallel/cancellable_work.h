// Work whose data-parallel loops another thread can cut short (RenderSession::abort): run(work)
// runs it in a oneTBB task group, and cancel() cancels that group, so every parallel_for of the work
// (nested loops bind to the group) skips the chunks it has not started, and every later loop of the
// work runs none. Sequential code between the loops still runs. What the work leaves is therefore
// incomplete, and the caller must discard it.
#pragma once

#include <tbb/task.h>
#include <tbb/task_group.h>

#include <mutex>

namespace pathspace {

// True inside work that CancellableWork::cancel() cut short: a step that would change state kept
// beyond the pass (a path space filter's table) can stop before it, so the cut leaves that state
// as it was.
inline bool work_cancelled() {
  tbb::task_group_context* context = tbb::task::current_context();
  return context && context->is_group_execution_cancelled();
}

class CancellableWork {
 public:
  // Runs work() on the calling thread; true when it ran to the end without a cancel(). An exception
  // from work() propagates, unless the work was cancelled: it is then part of what is discarded
  // (a loop that skipped its chunks can leave data that a later check rejects).
  template <typename Work>
  bool run(const Work& work) {
    tbb::task_group group;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      running_ = &group;
      cancelled_ = false;
    }
    try {
      group.run_and_wait(work);
    } catch (...) {
      if (!stop_running()) throw;  // an exception of its own, not of a cancelled loop
      return false;
    }
    return !stop_running();
  }

  // Thread-safe. Cancels the work running now; does nothing when none runs.
  void cancel() {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!running_) return;
    cancelled_ = true;
    running_->cancel();
  }

 private:
  // Ends the run; true when it was cancelled.
  bool stop_running() {
    std::lock_guard<std::mutex> lock(mutex_);
    running_ = nullptr;
    return cancelled_;
  }

  std::mutex mutex_;
  tbb::task_group* running_ = nullptr;  // the work running now
  bool cancelled_ = false;               // cancel() was called during it
};

}  // namespace pathspace
