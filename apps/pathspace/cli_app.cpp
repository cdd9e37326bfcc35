#include "cli_app.h"

#include <algorithm>
#include <cctype>
#include <csignal>
#include <cstdio>
#include <exception>
#include <new>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "pathspace/base/printable.h"
#include "pathspace/options/option_spec.h"
#include "job_group.h"
#include "pathspace/options/usage_error.h"

namespace pathspace::cli {

namespace {

constexpr int kExitFailure = 1;
constexpr int kExitUsage = 2;

// CLI11 messages can span lines; the contract is one line per error. Every message passes through
// here, so input it quotes (a scene file's bytes, a command-line word) is shown with escapes.
std::string one_line(std::string s) {
  for (char& c : s)
    if (c == '\n') c = ' ';
  while (!s.empty() && s.back() == ' ') s.pop_back();
  return printable(s);
}

// CLI11 reports a word that is no command as an unexpected argument; name the commands instead.
void check_command_word(const CLI::App& app, int argc, char** argv) {
  if (argc < 2 || argv[1][0] == '-') return;
  std::string names;
  for (const CLI::App* sub : app.get_subcommands({})) {
    if (sub->check_name(argv[1])) return;
    names += (names.empty() ? "" : ", ") + sub->get_name();
  }
  throw UsageError("unknown command '" + std::string(argv[1]) + "' (commands: " + names + ")", "run 'pathspace --help' for usage");
}

// An empty value ("-r ''", "--resume ''", "--scenes ''") names nothing; the options' own code would
// take it as "not given" and fall back to a default. Checked once here for every option that takes
// values, in every parsed command.
void check_no_empty_values(const CLI::App& app) {
  for (const CLI::Option* opt : app.get_options()) {
    if (opt->get_type_size_min() <= 0) continue;  // flags
    for (const std::string& value : opt->results())
      if (value.empty()) throw UsageError("option " + opt->get_name() + " has an empty value");
  }
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App* s) { return s->parsed(); })) check_no_empty_values(*sub);
}

// CLI11 2.1 takes a "--" right after an option's list of values (-o a.exr b.png -- scene) as the end
// of that list and then reads options again, so "-o a.exr -- -odd.pbrt" read "-odd.pbrt" as
// "-o dd.pbrt". In pathspace, as in every Unix tool, "--" ends option parsing: every word after it
// is a positional argument. Where CLI11 would spend the "--" on a value list, a second one follows.
std::vector<std::string> with_positional_mark(const CLI::App& app, int argc, char** argv) {
  std::vector<std::string> words(argv, argv + argc);
  const auto mark = std::find(words.begin() + std::min(argc, 2), words.end(), "--");
  if (mark == words.end() || argc < 2) return words;
  const CLI::App* command = nullptr;
  for (const CLI::App* sub : app.get_subcommands({}))
    if (sub->check_name(words[1])) command = sub;
  if (!command) return words;
  auto is_option = [](const std::string& w) {
    return w.size() > 1 && w[0] == '-' && !(std::isdigit(static_cast<unsigned char>(w[1])) || w[1] == '.');
  };
  // The option whose values end at the mark, and how many it has.
  int values = 0;
  auto it = mark;
  while (it != words.begin() + 2 && !is_option(*(it - 1))) --it, ++values;
  if (it == words.begin() + 2) return words;
  std::string name = *(it - 1);
  if (name.rfind("--", 0) == 0 && name.find('=') != std::string::npos) name.erase(name.find('=')), ++values;
  else if (name.rfind("--", 0) != 0 && name.size() > 2) name.erase(2), ++values;  // -oVALUE
  const CLI::Option* opt = command->get_option_no_throw(name);
  if (opt && opt->get_items_expected_max() > values) words.insert(mark, "--");
  return words;
}

}  // namespace

CliApp::CliApp() : app("pathspace: path space filtering and pixel cache light tracing renderer", "pathspace") {
  app.require_subcommand(1);
  render_cmd = add_render_command(app, &render_options);
  info_cmd = add_info_command(app, &info_options);
  compare_cmd = add_compare_command(app, &compare_options);
  study_cmd = add_study_command(app, &study_options);
#if PATHSPACE_HAVE_VIEWER
  view_cmd = add_view_command(app, &view_options);
#endif
}

void CliApp::parse(int argc, char** argv) {
  check_command_word(app, argc, argv);
  std::vector<std::string> words = with_positional_mark(app, argc, argv);
  std::vector<char*> marked;
  for (std::string& w : words) marked.push_back(w.data());
  app.parse(int(marked.size()), marked.data());
  check_no_empty_values(app);
}

int CliApp::run() {
  if (render_cmd->parsed()) return run_render_command(render_options, *render_cmd);
  if (info_cmd->parsed()) return run_info_command(info_options);
  if (compare_cmd->parsed()) return run_compare_command(compare_options);
  if (study_cmd->parsed()) return run_study_command(study_options);
#if PATHSPACE_HAVE_VIEWER
  if (view_cmd->parsed()) return run_view_command(view_options, *view_cmd);
#endif
  return 0;
}

std::string CliApp::command_name() const {
  if (render_cmd->parsed()) return "pathspace render";
  if (info_cmd->parsed()) return "pathspace info";
  if (compare_cmd->parsed()) return "pathspace compare";
  if (study_cmd->parsed()) return "pathspace study " + study_options.study;
#if PATHSPACE_HAVE_VIEWER
  if (view_cmd->parsed()) return "pathspace view";
#endif
  return "pathspace";
}

int run_cli(int argc, char** argv) {
  // A closed pipe on stdout or stderr (`pathspace render ... | head -1`) is an error of the write,
  // not a signal that kills the render before it writes its outputs: progress then goes quiet.
  std::signal(SIGPIPE, SIG_IGN);
  CliApp cli;
  try {
    cli.parse(argc, argv);
    return cli.run();
  } catch (const CLI::CallForHelp& e) {
    return cli.app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return cli.app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::string sub = cli.render_cmd->parsed()    ? " render"
                      : cli.info_cmd->parsed()    ? " info"
                      : cli.compare_cmd->parsed() ? " compare"
                      : cli.study_cmd->parsed()   ? " study"
                                                  : "";
#if PATHSPACE_HAVE_VIEWER
    if (cli.view_cmd->parsed()) sub = " view";
#endif
    fmt::print(stderr, "pathspace{}: error: {} (run 'pathspace{} --help' for usage)\n", sub, one_line(e.what()), sub);
    return kExitUsage;
  } catch (const UsageError& e) {
    const std::string command = cli.command_name();
    const std::string hint = e.hint().empty() ? "run '" + command + " --help' for usage" : e.hint();
    if (!error_printed_by_rank0()) fmt::print(stderr, "{}: error: {} ({})\n", command, one_line(e.what()), hint);
    return kExitUsage;
  } catch (const OptionError& e) {
    const std::string command = cli.command_name();
    fmt::print(stderr, "{}: error: {} (run '{} --help' for usage)\n", command, one_line(e.what()), command);
    return kExitUsage;
  } catch (const std::bad_alloc&) {
    // A scene file's reader names its file (io/scene_loader.cpp); what is left is the render's own
    // memory: the image, the filter's tables, the photons.
    if (!error_printed_by_rank0())
      fmt::print(stderr, "{}: error: out of memory (the image size, samples kept per pixel or a filter's tables need more than is "
                         "available; try a smaller -r or table)\n", cli.command_name());
    return kExitFailure;
  } catch (const std::exception& e) {
    if (!error_printed_by_rank0()) fmt::print(stderr, "{}: error: {}\n", cli.command_name(), one_line(e.what()));
    return kExitFailure;
  }
}

}  // namespace pathspace::cli
