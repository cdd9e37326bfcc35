// Minimal leveled logging to stderr (host only). Warnings about user input use this.
#pragma once

#include <fmt/core.h>

#include <cstdio>
#include <utility>

namespace pathspace::log {

enum class Level { quiet = 0, warning = 1, info = 2 };

inline Level& level() {
  static Level current = Level::info;
  return current;
}

template <typename... Args>
void warning(fmt::format_string<Args...> f, Args&&... args) {
  if (level() >= Level::warning) fmt::print(stderr, "warning: {}\n", fmt::format(f, std::forward<Args>(args)...));
}

template <typename... Args>
void info(fmt::format_string<Args...> f, Args&&... args) {
  if (level() >= Level::info) fmt::print(stderr, "{}\n", fmt::format(f, std::forward<Args>(args)...));
}

}  // namespace pathspace::log
