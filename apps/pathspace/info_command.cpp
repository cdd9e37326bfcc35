#include "info_command.h"

#include <fmt/format.h>

#include "pathspace/integrators/integrator.h"
#include "pathspace/integrators/render.h"
#include "pathspace/scene/builtin_scenes.h"

namespace pathspace::cli {

CLI::App* add_info_command(CLI::App& app, InfoOptions* options) {
  CLI::App* cmd = app.add_subcommand("info", "List built-in scenes, integrators and the build");
  cmd->add_flag("--scenes", options->scenes, "List the built-in scenes (name and id)");
  cmd->add_flag("--integrators", options->integrators, "List the integrators");
  return cmd;
}

int run_info_command(const InfoOptions& options) {
  const bool all = !options.scenes && !options.integrators;
  if (all) fmt::print("pathspace {} build\n\n", build_type());
  if (all || options.scenes) {
    fmt::print("Built-in scenes (select by name or id; default '{}'):\n", kDefaultSceneName);
    for (const BuiltinSceneInfo& s : builtin_scenes()) fmt::print("  {:<28} {:<6} {}\n", s.name, s.id, s.description);
  }
  if (all || options.integrators) {
    if (all) fmt::print("\n");
    fmt::print("Integrators:\n");
    for (const std::string& name : integrator_names()) fmt::print("  {}\n", name);
  }
  return 0;
}

}  // namespace pathspace::cli
