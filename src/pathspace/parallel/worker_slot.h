// Which CPU worker is running the calling code, for per-worker buffers (film/splat_film.h): a slot
// index unique among the threads running at once, below worker_slot_count(). oneTBB's arena slots.
#pragma once

#include <tbb/task_arena.h>

namespace pathspace {

// -1 outside any worker (tbb::task_arena::not_initialized); the main thread that starts a
// parallel_for takes part in it as slot 0.
inline int worker_slot() { return tbb::this_task_arena::current_thread_index(); }
inline int worker_slot_count() { return tbb::this_task_arena::max_concurrency(); }

}  // namespace pathspace
