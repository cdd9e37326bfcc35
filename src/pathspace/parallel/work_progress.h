// How much data-parallel work this process has started and finished: parallel_for adds every loop's
// item count when it starts and every chunk's when it ends. A long render pass can so report how
// far it is (RenderSession::pass_progress) without the integrators knowing about progress; the cost
// is one atomic add per chunk.
#pragma once

#include <atomic>
#include <cstdint>

namespace pathspace {

struct WorkProgress {
  uint64_t started = 0, done = 0;  // items, over every parallel_for so far
};

namespace detail {
inline std::atomic<uint64_t> g_work_started{0};
inline std::atomic<uint64_t> g_work_done{0};
}  // namespace detail

inline WorkProgress work_progress() {
  WorkProgress w;
  w.done = detail::g_work_done.load(std::memory_order_relaxed);  // done first: done <= started
  w.started = detail::g_work_started.load(std::memory_order_relaxed);
  return w;
}

}  // namespace pathspace
