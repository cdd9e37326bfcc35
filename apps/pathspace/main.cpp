// pathspace command line: `render`, `info`, `compare` and `study` (docs/cli.md). Usage mistakes exit with status 2 and
// one line on stderr; failures while running exit with status 1.
#include <cstdio>
#include <exception>
#include <string>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "compare_command.h"
#include "pathspace/base/printable.h"
#include "pathspace/options/option_spec.h"
#include "info_command.h"
#include "render_command.h"
#include "study_command.h"
#include "usage_error.h"

namespace {

constexpr int kExitFailure = 1;
constexpr int kExitUsage = 2;

// CLI11 messages can span lines; the contract is one line per error. Every message passes through
// here, so input it quotes (a scene file's bytes, a command-line word) is shown with escapes.
std::string one_line(std::string s) {
  for (char& c : s)
    if (c == '\n') c = ' ';
  while (!s.empty() && s.back() == ' ') s.pop_back();
  return pathspace::printable(s);
}

// CLI11 reports a word that is no command as an unexpected argument; name the commands instead.
void check_command_word(const CLI::App& app, int argc, char** argv) {
  if (argc < 2 || argv[1][0] == '-') return;
  std::string names;
  for (const CLI::App* sub : app.get_subcommands({})) {
    if (sub->check_name(argv[1])) return;
    names += (names.empty() ? "" : ", ") + sub->get_name();
  }
  throw pathspace::cli::UsageError("unknown command '" + std::string(argv[1]) + "' (commands: " + names + ")",
                                   "run 'pathspace --help' for usage");
}

}  // namespace

int main(int argc, char** argv) {
  using namespace pathspace::cli;
  CLI::App app("pathspace: path space filtering and pixel cache light tracing renderer", "pathspace");
  app.require_subcommand(1);
  RenderOptions render_options;
  InfoOptions info_options;
  CompareOptions compare_options;
  StudyCommandOptions study_options;
  CLI::App* render_cmd = add_render_command(app, &render_options);
  CLI::App* info_cmd = add_info_command(app, &info_options);
  CLI::App* compare_cmd = add_compare_command(app, &compare_options);
  CLI::App* study_cmd = add_study_command(app, &study_options);

  std::string command = "pathspace";
  try {
    check_command_word(app, argc, argv);
    app.parse(argc, argv);
    if (render_cmd->parsed()) {
      command = "pathspace render";
      return run_render_command(render_options, *render_cmd);
    }
    if (info_cmd->parsed()) {
      command = "pathspace info";
      return run_info_command(info_options);
    }
    if (compare_cmd->parsed()) {
      command = "pathspace compare";
      return run_compare_command(compare_options);
    }
    if (study_cmd->parsed()) {
      command = "pathspace study " + study_options.study;
      return run_study_command(study_options);
    }
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    const std::string sub = render_cmd->parsed()    ? " render"
                            : info_cmd->parsed()    ? " info"
                            : compare_cmd->parsed() ? " compare"
                            : study_cmd->parsed()   ? " study"
                                                    : "";
    fmt::print(stderr, "pathspace{}: error: {} (run 'pathspace{} --help' for usage)\n", sub, one_line(e.what()), sub);
    return kExitUsage;
  } catch (const UsageError& e) {
    const std::string hint = e.hint().empty() ? "run '" + command + " --help' for usage" : e.hint();
    fmt::print(stderr, "{}: error: {} ({})\n", command, one_line(e.what()), hint);
    return kExitUsage;
  } catch (const pathspace::OptionError& e) {
    fmt::print(stderr, "{}: error: {} (run '{} --help' for usage)\n", command, one_line(e.what()), command);
    return kExitUsage;
  } catch (const std::exception& e) {
    fmt::print(stderr, "{}: error: {}\n", command, one_line(e.what()));
    return kExitFailure;
  }
  return 0;
}
