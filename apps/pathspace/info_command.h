// `pathspace info`: lists the built-in scenes, the integrators and filters with their options (from
// the registry, as text or --json for tools), the build, and what a checkpoint or scene file holds.
#pragma once

#include <string>

#include <CLI/CLI.hpp>

namespace pathspace::cli {

struct InfoOptions {
  bool scenes = false;
  bool integrators = false;
  bool json = false;
  bool markdown = false;
  std::string file;  // a checkpoint (render --checkpoint) or scene file to describe
};

CLI::App* add_info_command(CLI::App& app, InfoOptions* options);
int run_info_command(const InfoOptions& options);

}  // namespace pathspace::cli
