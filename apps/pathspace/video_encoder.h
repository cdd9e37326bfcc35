// `render --frames ... --video out.mp4`: encodes the frames' PNG sequence with the ffmpeg program
// (H.264, yuv420p, installed by scripts/install-deps). The video is written under a temporary name and
// renamed, like every output.
#pragma once

#include <cstdint>
#include <string>

namespace pathspace::cli {

// The ffmpeg program on PATH, or empty.
std::string find_ffmpeg();

// Encodes `png_pattern` (printf-style frame number, e.g. out/frame-%04d.png) from frame `first` on at
// `fps` into `video`. Throws pathspace::Error with ffmpeg's message when it fails.
void encode_video(const std::string& ffmpeg, const std::string& png_pattern, uint64_t first, double fps, const std::string& video);

}  // namespace pathspace::cli
