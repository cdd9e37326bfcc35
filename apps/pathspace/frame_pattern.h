// Output names of a frame sequence: one printf-style frame number in the name, %d or %0Nd
// (out/frame-%04d.exr), the form ffmpeg reads too.
#pragma once

#include <cstdint>
#include <string>

namespace pathspace::cli {

// Throws UsageError naming `option` unless `pattern` holds exactly one %d or %0Nd (N from 1 to 9) and
// no other '%'.
void check_frame_pattern(const std::string& option, const std::string& pattern);
// The pattern with its placeholder replaced by `frame` (zero-padded to N digits for %0Nd).
std::string frame_path(const std::string& pattern, uint64_t frame);

}  // namespace pathspace::cli
