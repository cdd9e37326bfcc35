// `pathspace compare IMAGE REFERENCE`: MSE, relMSE, block relMSE, blotched-block share and FLIP of an
// image against a reference (docs/cli.md).
#pragma once

#include <string>

#include <CLI/CLI.hpp>

#include "pathspace/film/block_metrics.h"
#include "pathspace/film/flip.h"

namespace pathspace::cli {

struct CompareOptions {
  std::string image, reference;
  std::string reference_variance;  // optional variance-of-the-mean image of the reference
  std::string error_map;           // optional output: per-pixel relative squared error
  int block = kDefaultMetricBlock;  // side of the blocks of block relMSE and the blotched share
  double flip_ppd = kFlipPixelsPerDegree;
  bool json = false;
};

CLI::App* add_compare_command(CLI::App& app, CompareOptions* options);
int run_compare_command(const CompareOptions& options);

}  // namespace pathspace::cli
