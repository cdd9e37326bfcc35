#include "registry_options.h"

#include <fmt/format.h>

#include "pathspace/integrators/integrator_registry.h"
#include "pathspace/session/option_catalog.h"

namespace pathspace::cli {

namespace {

std::string join(const std::vector<std::string>& names) { return fmt::format("{}", fmt::join(names, ", ")); }

std::string value_hint(const OptionSpec& spec) {
  switch (spec.type) {
    case OptionType::integer: return "INT";
    case OptionType::real: return "REAL";
    case OptionType::choice: return join(spec.choices);
    case OptionType::size: return "WxH";
    case OptionType::flag: return "";
  }
  return "";
}

}  // namespace

const char* short_alias(const std::string& name) { return name == "max-depth" ? "-d" : nullptr; }

std::vector<RegistryOption> registry_options() {
  std::vector<RegistryOption> out;
  for (CatalogOption& o : option_catalog()) out.push_back({std::move(o.spec), std::move(o.integrators), std::move(o.filters), {}});
  const size_t all = integrator_registry().entries().size();
  for (RegistryOption& o : out) {
    if (!o.filters.empty())
      o.group = "Filter " + join(o.filters) + " (--filter " + o.filters.front() + ")";
    else if (o.integrators.size() == all && all > 1)
      o.group = "Every integrator";
    else
      o.group = "Integrator " + join(o.integrators) + " (--integrator " + o.integrators.front() + ")";
  }
  return out;
}

void RegistryOptionParser::add_to(CLI::App* cmd) {
  options_ = registry_options();
  for (const RegistryOption& o : options_) {
    const OptionSpec& s = o.spec;
    std::string names = "--" + s.name;
    if (const char* alias = short_alias(s.name)) names = std::string(alias) + "," + names;
    std::string help = s.help;
    if (s.type != OptionType::flag) help += fmt::format(" (default: {})", s.default_text);
    if (s.type == OptionType::integer || s.type == OptionType::real)
      help += fmt::format(" [{} to {}]", s.min, s.max);
    if (!s.paper.empty()) help += " [" + s.paper + "]";
    // add_flag(name, std::string&) would bind a variable, so the flag's help is set separately.
    CLI::Option* opt = s.type == OptionType::flag ? cmd->add_flag(names)->description(help) : cmd->add_option(names, values_[s.name], help);
    if (s.type != OptionType::flag) opt->type_name(value_hint(s));
    opt->group(o.group);
    cli_[s.name] = opt;
  }
}

OptionValues RegistryOptionParser::given() const {
  OptionValues out;
  for (const auto& [name, opt] : cli_) {
    if (opt->count() == 0) continue;
    const auto it = values_.find(name);
    out.set(name, it == values_.end() ? std::string() : it->second);
  }
  return out;
}

}  // namespace pathspace::cli
