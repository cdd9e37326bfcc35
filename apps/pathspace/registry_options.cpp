#include "registry_options.h"

#include <fmt/format.h>

#include "pathspace/base/error.h"
#include "pathspace/filters/filter_registry.h"
#include "pathspace/integrators/integrator_registry.h"

namespace pathspace::cli {

namespace {

std::string join(const std::vector<std::string>& names) { return fmt::format("{}", fmt::join(names, ", ")); }

void merge(std::vector<RegistryOption>* out, const OptionSpec& spec, const std::string& integrator, const std::string& filter) {
  for (RegistryOption& o : *out) {
    if (o.spec.name != spec.name) continue;
    if (!o.spec.same_contract(spec))
      throw Error(fmt::format("option --{} is defined with different types, ranges or defaults by {} and {}", spec.name,
                              join(o.integrators), integrator.empty() ? filter : integrator));
    if (!integrator.empty()) o.integrators.push_back(integrator);
    if (!filter.empty()) o.filters.push_back(filter);
    return;
  }
  RegistryOption o{spec, {}, {}, {}};
  if (!integrator.empty()) o.integrators.push_back(integrator);
  if (!filter.empty()) o.filters.push_back(filter);
  out->push_back(std::move(o));
}

std::string value_hint(const OptionSpec& spec) {
  switch (spec.type) {
    case OptionType::integer: return "INT";
    case OptionType::real: return "REAL";
    case OptionType::choice: return join(spec.choices);
    case OptionType::flag: return "";
  }
  return "";
}

}  // namespace

const char* short_alias(const std::string& name) { return name == "max-depth" ? "-d" : nullptr; }

std::vector<RegistryOption> registry_options() {
  std::vector<RegistryOption> out;
  for (const IntegratorEntry& e : integrator_registry().entries())
    for (const OptionSpec& spec : e.schema.options) merge(&out, spec, e.name, "");
  for (const FilterEntry& e : filter_registry().entries())
    for (const OptionSpec& spec : e.schema.options) merge(&out, spec, "", e.name);
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
