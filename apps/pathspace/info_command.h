// `pathspace info`: lists the built-in scenes, the integrators and the build.
#pragma once

#include <CLI/CLI.hpp>

namespace pathspace::cli {

struct InfoOptions {
  bool scenes = false;
  bool integrators = false;
};

CLI::App* add_info_command(CLI::App& app, InfoOptions* options);
int run_info_command(const InfoOptions& options);

}  // namespace pathspace::cli
