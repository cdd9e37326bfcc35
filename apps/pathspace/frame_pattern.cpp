#include "frame_pattern.h"

#include <fmt/format.h>

#include "pathspace/options/usage_error.h"

namespace pathspace::cli {

namespace {

struct Placeholder {
  size_t begin = std::string::npos, end = 0;  // [begin, end) in the pattern
  int width = 0;                              // 0: %d
};

// The placeholder, or begin == npos when the pattern has none or another '%'.
Placeholder find_placeholder(const std::string& p, int* percents) {
  Placeholder found;
  *percents = 0;
  for (size_t i = 0; i < p.size(); ++i) {
    if (p[i] != '%') continue;
    ++*percents;
    size_t j = i + 1;
    int width = 0;
    if (j < p.size() && p[j] == '0' && j + 1 < p.size() && p[j + 1] >= '1' && p[j + 1] <= '9') {
      width = p[j + 1] - '0';
      j += 2;
    }
    if (j < p.size() && p[j] == 'd') found = {i, j + 1, width};
  }
  return found;
}

}  // namespace

void check_frame_pattern(const std::string& option, const std::string& pattern) {
  int percents = 0;
  const Placeholder p = find_placeholder(pattern, &percents);
  if (p.begin == std::string::npos || percents != 1)
    throw UsageError(fmt::format("{} '{}': with --frames, a file name needs exactly one frame number, %d or %0Nd", option, pattern),
                     "e.g. -o out/frame-%04d.exr");
}

std::string frame_path(const std::string& pattern, uint64_t frame) {
  int percents = 0;
  const Placeholder p = find_placeholder(pattern, &percents);
  if (p.begin == std::string::npos) return pattern;
  const std::string number = p.width > 0 ? fmt::format("{:0{}}", frame, p.width) : std::to_string(frame);
  // Appended piecewise: operator+ on these trips GCC 12's false -Wrestrict (PR 105329).
  std::string out = pattern.substr(0, p.begin);
  out.append(number).append(pattern, p.end, std::string::npos);
  return out;
}

}  // namespace pathspace::cli
