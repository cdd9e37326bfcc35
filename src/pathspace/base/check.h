// Internal invariants (programming errors, not user errors). Active in every build type:
// a broken invariant in a renderer silently produces wrong images, which is worse than a stop.
#pragma once

#include "pathspace/base/platform.h"

#if !PS_DEVICE_CODE
#include <cstdio>
#include <cstdlib>
#endif

namespace pathspace::detail {
#if !PS_DEVICE_CODE
[[noreturn]] inline void check_failed(const char* expr, const char* file, int line) {
  std::fprintf(stderr, "pathspace: internal check failed: %s (%s:%d)\n", expr, file, line);
  std::abort();
}
#endif
}  // namespace pathspace::detail

#if PS_DEVICE_CODE
#define PS_CHECK(expr) ((void)0)
#else
#define PS_CHECK(expr) ((expr) ? (void)0 : ::pathspace::detail::check_failed(#expr, __FILE__, __LINE__))
#endif
