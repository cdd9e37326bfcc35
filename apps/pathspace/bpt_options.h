// The bidirectional path tracing options of `pathspace render` (--bpt-*), docs/cli.md. The MIS
// heuristic comes from --mis and the path length limit from --max-depth, as for PT.
#pragma once

#include <string>

#include <CLI/CLI.hpp>

#include "pathspace/integrators/integrator.h"

namespace pathspace::cli {

struct BptOptions {
  int strategy_images = 0;  // > 0: write one image per strategy (s, t) up to this path length
  double splat_scale = 0.0;
};

void add_bpt_options(CLI::App* cmd, BptOptions* o);
// Fills settings->bpt (after settings->pt is set). Throws UsageError.
void apply_bpt_options(const BptOptions& o, const std::string& integrator, IntegratorSettings* settings);
// Whether the integrator's AOVs (the per-strategy images) should be written.
inline bool bpt_wants_aovs(const BptOptions& o) { return o.strategy_images > 0; }

}  // namespace pathspace::cli
