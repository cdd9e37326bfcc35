// parallel_for(n, body): the one way pathspace runs data-parallel loops on the CPU (oneTBB now; the
// CUDA backend maps the same bodies to launches). body(begin, end) gets a contiguous index range.
// ThreadLimit caps the worker count for its lifetime (--threads). Every loop counts its items in
// work_progress() (progress inside a render pass).
#pragma once

#include <tbb/blocked_range.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <cstddef>
#include <memory>

#include "pathspace/parallel/work_progress.h"

namespace pathspace {

template <typename Body>
void parallel_for(size_t n, size_t grain, const Body& body) {
  detail::g_work_started.fetch_add(n, std::memory_order_relaxed);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, n, grain == 0 ? 1 : grain), [&](const tbb::blocked_range<size_t>& r) {
    body(r.begin(), r.end());
    detail::g_work_done.fetch_add(r.size(), std::memory_order_relaxed);
  });
}

class ThreadLimit {
 public:
  // threads <= 0 keeps TBB's default (all cores).
  explicit ThreadLimit(int threads) {
    if (threads > 0)
      control_ = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, size_t(threads));
  }
  static int active() { return int(tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism)); }

 private:
  std::unique_ptr<tbb::global_control> control_;
};

}  // namespace pathspace
