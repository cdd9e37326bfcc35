// `pathspace compare IMAGE REFERENCE`: MSE and relMSE of an image against a reference (docs/cli.md).
#pragma once

#include <string>

#include <CLI/CLI.hpp>

namespace pathspace::cli {

struct CompareOptions {
  std::string image, reference;
  std::string reference_variance;  // optional variance-of-the-mean image of the reference
  std::string error_map;           // optional output: per-pixel relative squared error
  bool json = false;
};

CLI::App* add_compare_command(CLI::App& app, CompareOptions* options);
int run_compare_command(const CompareOptions& options);

}  // namespace pathspace::cli
