// The SPPM options of `pathspace render` (--photons, --sppm-*), docs/cli.md.
#pragma once

#include <cstdint>
#include <string>

#include <CLI/CLI.hpp>

#include "pathspace/integrators/integrator.h"

namespace pathspace::cli {

struct SppmOptions {
  uint64_t photons = 0;   // 0: one per pixel
  float alpha = 2.f / 3.f;
  float radius = 0.f;     // 0: 1% of the scene's bounding radius
  float glossy_roughness = 0.f;
};

void add_sppm_options(CLI::App* cmd, SppmOptions* o);
// Fills settings->sppm (the path length limit comes from --max-depth via settings->pt). Throws UsageError.
void apply_sppm_options(const SppmOptions& o, const std::string& integrator, IntegratorSettings* settings);

}  // namespace pathspace::cli
