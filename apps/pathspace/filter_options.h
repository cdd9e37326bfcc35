// The path space filter options of `pathspace render` (--filter and --psf-*), docs/cli.md.
#pragma once

#include <string>

#include <CLI/CLI.hpp>

#include "pathspace/integrators/integrator.h"

namespace pathspace::cli {

struct FilterOptions {
  std::string filter = "none";
  std::string select = "first";
  int nth = 1;
  int max_vertices = 2;
  float min_roughness = 0.1f;
  bool no_layers = false;
  float scale = 12.f;
  bool no_jitter = false;
  std::string normal = "key";
  float table_factor = 1.f;
  int probes = 16;
  int min_count = 4;
  bool neighbours = false;
  bool multi_level = false;
  bool aovs = false;
};

void add_filter_options(CLI::App* cmd, FilterOptions* o);
// Fills settings->filter and settings->pt.selection. Throws UsageError.
void apply_filter_options(const FilterOptions& o, IntegratorSettings* settings);

}  // namespace pathspace::cli
