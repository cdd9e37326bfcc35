// BackgroundJob: one job at a time on its own thread, so that a render can hand slow file writes
// (periodic outputs, checkpoints) off between passes instead of stalling the next pass. The render
// thread asks busy() and skips a periodic write while the previous one still runs. The job's thread
// runs at a lower scheduling priority (nice +10), so on a machine whose cores all render, encoding
// and writing take the time the render leaves rather than time from the render. It counts the jobs
// it ran and the CPU time they took, which is what they could have taken from the render.
#pragma once

#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <ctime>
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
    job_ = std::async(std::launch::async, [this, job = std::move(job)] {
      // Linux: niceness is per thread; failure only leaves the default priority.
      (void)::setpriority(PRIO_PROCESS, id_t(::syscall(SYS_gettid)), kNiceness);
      job();
      cpu_ns_ += thread_cpu_ns();  // a new thread per job: its CPU time is the job's
      ++jobs_;
    });
  }
  uint64_t jobs_done() const { return jobs_.load(); }
  double cpu_seconds() const { return double(cpu_ns_.load()) * 1e-9; }
  // Waits for the running job, if any, and rethrows its exception.
  void wait() {
    if (job_.valid()) job_.get();
  }

 private:
  static uint64_t thread_cpu_ns() {
    timespec t{};
    ::clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return uint64_t(t.tv_sec) * 1000000000ull + uint64_t(t.tv_nsec);
  }

  static constexpr int kNiceness = 10;
  std::future<void> job_;
  std::atomic<uint64_t> cpu_ns_{0}, jobs_{0};
};

}  // namespace pathspace
