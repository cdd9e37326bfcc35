// The light tracing options of `pathspace render` (--light-paths and --lt-*), docs/cli.md.
#pragma once

#include <cstdint>
#include <string>

#include <CLI/CLI.hpp>

#include "pathspace/integrators/integrator.h"

namespace pathspace::cli {

struct LtOptions {
  uint64_t light_paths = 0;  // 0: one per pixel
  bool skip_emitter = false;
  std::string filter = "box";
  float filter_radius = 1.5f;
  double splat_scale = 0.0;
};

void add_lt_options(CLI::App* cmd, LtOptions* o);
// Fills settings->lt (the path length limit comes from --max-depth via settings->pt). Throws UsageError.
void apply_lt_options(const LtOptions& o, const std::string& integrator, IntegratorSettings* settings);

}  // namespace pathspace::cli
