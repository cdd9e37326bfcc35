// The integrator and filter options of `pathspace render`, built from the registry
// (integrators/integrator_registry.h, filters/filter_registry.h): every option of every registered
// integrator and filter becomes one command-line option, grouped in --help under the integrators or
// filter it belongs to. The CLI defines none of them itself; validation is configure_render's.
#pragma once

#include <map>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "pathspace/options/option_spec.h"
#include "pathspace/options/option_values.h"

namespace pathspace::cli {

// One command-line option and the registry entries that define it.
struct RegistryOption {
  OptionSpec spec;
  std::vector<std::string> integrators, filters;
  std::string group;  // the --help group
};

// Every option of the catalog (session/option_catalog.h), with its --help group.
std::vector<RegistryOption> registry_options();

class RegistryOptionParser {
 public:
  // Adds the options to cmd.
  void add_to(CLI::App* cmd);
  // The options given on the command line, by name (flags with an empty value).
  OptionValues given() const;

 private:
  std::vector<RegistryOption> options_;
  std::map<std::string, CLI::Option*> cli_;
  std::map<std::string, std::string> values_;
};

// Short aliases for a few frequent options ("-d" for --max-depth).
const char* short_alias(const std::string& name);

}  // namespace pathspace::cli
