// The statistics of a render as JSON: what `pathspace render --stats FILE` writes (docs/cli.md) and
// what the Python bindings return as RenderResult.stats (docs/python.md): what ran, how long, how fast.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "pathspace/options/option_values.h"
#include "pathspace/session/render_session.h"

namespace pathspace {

// What the statistics say about the render besides the session's own counters.
struct RenderRunInfo {
  std::string scene;
  int width = 0, height = 0;
  int max_segments = 0;
  std::string outputs;  // comma-separated output files
};

// RenderRunInfo::max_segments: the path length limit given as --max-depth, else the scene's.
int max_segments_of(const OptionValues& given, const Scene& scene);

nlohmann::ordered_json render_stats_object(const RenderStats& stats, const RenderRunInfo& run);
// The same, indented, with a final newline.
std::string render_stats_json(const RenderStats& stats, const RenderRunInfo& run);
// The integrator's and filter's typed statistics: name -> number (text or histogram bins).
nlohmann::ordered_json statistics_json(const Statistics& statistics);
// A distributed render's per-rank lines for the summary (docs/distributed.md); empty for one process.
std::string format_rank_table(const RenderStats& stats);

}  // namespace pathspace
