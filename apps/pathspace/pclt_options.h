// The pixel cache light tracing options of `pathspace render` (--pclt-*), docs/cli.md; the paper's
// parameters: light paths per iteration, radius and alpha (eq. 1), projection filter (sec. 5.2),
// visibility shortcut and epsilon (sec. 5.3), hash map kind (sec. 4, fig. 8), cache capacity (sec. 6).
#pragma once

#include <cstdint>
#include <string>

#include <CLI/CLI.hpp>

#include "pathspace/integrators/integrator.h"

namespace pathspace::cli {

struct PcltOptions {
  uint64_t light_paths = 0;  // 0: one per pixel
  float alpha = 2.f / 3.f;
  float radius = 0.f;        // 0: 1% of the scene's bounding radius
  std::string filter = "box";
  float filter_radius = 1.5f;
  std::string visibility = "shadow-ray";
  float epsilon = 5e-4f;
  bool no_specular_emission = false;
  std::string hash_map = "chained";
  uint32_t stochastic_slots = 0;
  uint64_t cache_capacity = 0;
  bool stochastic_store = false;
};

void add_pclt_options(CLI::App* cmd, PcltOptions* o);
// Fills settings->pclt (the path length limit comes from --max-depth via settings->pt). Throws UsageError.
void apply_pclt_options(const PcltOptions& o, const std::string& integrator, IntegratorSettings* settings);

}  // namespace pathspace::cli
