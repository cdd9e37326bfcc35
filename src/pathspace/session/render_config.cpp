#include "pathspace/session/render_config.h"

namespace pathspace {

namespace {

// "--integrator pt, bpt" / "--filter hashed": where an option does apply.
std::string owners_of(const std::string& option) {
  std::string integrators, filters;
  for (const IntegratorEntry& e : integrator_registry().entries())
    if (e.schema.find(option)) integrators += (integrators.empty() ? "" : ", ") + e.name;
  for (const FilterEntry& e : filter_registry().entries())
    if (e.schema.find(option)) filters += (filters.empty() ? "" : ", ") + e.name;
  std::string out;
  if (!integrators.empty()) out = "--integrator " + integrators;
  if (!filters.empty()) out += (out.empty() ? "" : " or ") + std::string("--filter ") + filters;
  return out;
}

}  // namespace

void check_composition(const std::string& integrator, const std::string& filter) {
  const IntegratorEntry& entry = integrator_registry().at(integrator);
  if (filter == FilterChoice::kNone) return;
  filter_registry().at(filter);
  if (entry.composes_with(filter)) return;
  std::string takers;
  for (const IntegratorEntry& e : integrator_registry().entries())
    if (e.composes_with(filter)) takers += (takers.empty() ? "" : ", ") + e.name;
  throw OptionError("--filter " + filter + " applies to --integrator " + (takers.empty() ? "none" : takers) + ", not " + integrator);
}

RenderConfig configure_render(const std::string& integrator, const std::string& filter, const OptionValues& given) {
  check_composition(integrator, filter);
  const IntegratorEntry& entry = integrator_registry().at(integrator);
  const FilterEntry* filter_entry = filter == FilterChoice::kNone ? nullptr : &filter_registry().at(filter);
  for (const auto& [name, value] : given.items()) {
    if (entry.schema.find(name) || (filter_entry && filter_entry->schema.find(name))) continue;
    const std::string owners = owners_of(name);
    if (owners.empty()) throw OptionError("unknown option --" + name);
    throw OptionError("--" + name + " applies to " + owners + ", not to --integrator " + integrator +
                      (filter_entry ? " --filter " + filter : std::string()));
  }
  RenderConfig config;
  config.integrator = integrator;
  config.settings = entry.schema.defaults();
  entry.schema.apply(given, &config.settings);
  config.filter.name = filter;
  if (filter_entry) {
    config.filter.settings = filter_entry->schema.defaults();
    filter_entry->schema.apply(given, &config.filter.settings);
  }
  return config;
}

RenderConfig configure_run(const std::string& integrator, const std::string& filter, const OptionValues& given, uint64_t seed,
                           int threads, const std::string& device) {
  RenderConfig config = configure_render(integrator, filter, given);
  config.seed = seed;
  config.threads = threads;
  config.device = device;
  check_device(config.device, config.integrator, config.filter.name);
  return config;
}

}  // namespace pathspace
