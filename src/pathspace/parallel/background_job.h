// BackgroundJob: one job at a time on its own thread, so that a render can hand slow file writes
// (periodic outputs, checkpoints) off between passes instead of stalling the next pass. The render
// thread asks busy() and skips a periodic write while the previous one still runs. The job's thread
// runs at a lower scheduling priority (nice +10), so on a machine whose cores all render, encoding
// and writing take the time the render leaves rather than time from the render.
#pragma once

#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <chrono>
#include <functional>
#include <future>
#include <utility>

namespace pathspace {

class BackgroundJob {
 public:
  BackgroundJob() = default;
  // Waits for a running job; its error, if any, is dropped (call wait() to see it).
  ~BackgroundJob() {
    if (job_.valid()) job_.wait();
  }
  BackgroundJob(const BackgroundJob&) = delete;
  BackgroundJob& operator=(const BackgroundJob&) = delete;

  bool busy() const { return job_.valid() && job_.wait_for(std::chrono::seconds(0)) != std::future_status::ready; }
  // Waits for the previous job (rethrowing its exception), then starts `job`.
  void start(std::function<void()> job) {
    wait();
    job_ = std::async(std::launch::async, [job = std::move(job)] {
      // Linux: niceness is per thread; failure only leaves the default priority.
      (void)::setpriority(PRIO_PROCESS, id_t(::syscall(SYS_gettid)), kNiceness);
      job();
    });
  }
  // Waits for the running job, if any, and rethrows its exception.
  void wait() {
    if (job_.valid()) job_.get();
  }

 private:
  static constexpr int kNiceness = 10;
  std::future<void> job_;
};

}  // namespace pathspace
