// CLI options of bidirectional path tracing (bpt_options.h): --bpt-strategy-images writes the
// integrator's per-strategy AOVs through render_command's --aov file naming.
#include "bpt_options.h"

#include "usage_error.h"

namespace pathspace::cli {

void add_bpt_options(CLI::App* cmd, BptOptions* o) {
  const char* group = "Bidirectional path tracing (--integrator bpt)";
  cmd->add_option("--bpt-strategy-images", o->strategy_images,
                  "Also write one MIS-weighted image per strategy (s, t) for path lengths up to N segments, as "
                  "OUT.aov-bpt-sS-tT.exr (they sum to the image)")
      ->check(CLI::Range(0, 32))
      ->group(group);
  cmd->add_option("--bpt-splat-scale", o->splat_scale, "Fixed-point units per unit pixel value of t = 1 splats (0: 2^32)")
      ->check(CLI::Range(0.0, 1e18))
      ->group(group);
}

void apply_bpt_options(const BptOptions& o, const std::string& integrator, IntegratorSettings* settings) {
  const bool any = o.strategy_images != 0 || o.splat_scale != 0.0;
  if (any && integrator != "bpt") throw UsageError("--bpt-* options need --integrator bpt");
  BptSettings& bpt = settings->bpt;
  bpt.max_segments = settings->pt.max_segments;
  bpt.mis = settings->pt.mis;
  bpt.strategy_images = o.strategy_images;
  bpt.splat_scale = o.splat_scale;
}

}  // namespace pathspace::cli
