// The pathspace command line as an object: the commands and their options, parsing, running the
// parsed command, and the mapping of every error to an exit status and one line on stderr
// (usage 2, failure 1; docs/cli.md). main() is run_cli; the argv fuzz target (tests/fuzz/fuzz_cli.cpp)
// builds a CliApp and parses bytes into it.
#pragma once

#include <string>

#include <CLI/CLI.hpp>

#include "compare_command.h"
#include "info_command.h"
#include "render_command.h"
#include "study_command.h"
#if PATHSPACE_HAVE_VIEWER
#include "view_command.h"
#endif

namespace pathspace::cli {

struct CliApp {
  CliApp();
  CliApp(const CliApp&) = delete;
  CliApp& operator=(const CliApp&) = delete;

  // Throws CLI::ParseError or UsageError (an unknown command word names the commands).
  void parse(int argc, char** argv);
  // Runs the parsed command; its exit status.
  int run();
  // "pathspace render", ... for messages: the parsed command, or "pathspace".
  std::string command_name() const;

  CLI::App app;
  RenderOptions render_options;
  InfoOptions info_options;
  CompareOptions compare_options;
  StudyCommandOptions study_options;
  CLI::App* render_cmd = nullptr;
  CLI::App* info_cmd = nullptr;
  CLI::App* compare_cmd = nullptr;
  CLI::App* study_cmd = nullptr;
#if PATHSPACE_HAVE_VIEWER
  ViewOptions view_options;
  CLI::App* view_cmd = nullptr;
#endif
};

// Parses and runs argv; every error becomes its exit status and one line on stderr.
int run_cli(int argc, char** argv);

}  // namespace pathspace::cli
