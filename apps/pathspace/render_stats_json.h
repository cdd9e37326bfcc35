// The JSON written by `pathspace render --stats FILE`: what ran, how long, how fast (docs/cli.md).
#pragma once

#include <string>

#include "pathspace/session/render_session.h"

namespace pathspace::cli {

struct RenderRunInfo {
  std::string scene;
  int width = 0, height = 0;
  int max_segments = 0;
  std::string outputs;  // comma-separated output files
};

std::string render_stats_json(const RenderStats& stats, const RenderRunInfo& run);

}  // namespace pathspace::cli
