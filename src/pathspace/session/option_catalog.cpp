#include "pathspace/session/option_catalog.h"

#include <algorithm>

#include "pathspace/filters/filter_registry.h"
#include "pathspace/integrators/integrator_registry.h"

namespace pathspace {

namespace {

std::string joined(const std::vector<std::string>& names) {
  std::string out;
  for (const std::string& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

void merge(std::vector<CatalogOption>* out, const OptionSpec& spec, const std::string& integrator, const std::string& filter) {
  auto it = std::find_if(out->begin(), out->end(), [&](const CatalogOption& o) { return o.spec.name == spec.name; });
  if (it == out->end()) {
    out->push_back(CatalogOption{spec, {}, {}});
    it = out->end() - 1;
  } else if (!it->spec.same_contract(spec)) {
    throw Error("option --" + spec.name + " is defined with different types, ranges or defaults by " +
                joined(it->integrators.empty() ? it->filters : it->integrators) + " and " + (integrator.empty() ? filter : integrator));
  }
  if (!integrator.empty()) it->integrators.push_back(integrator);
  if (!filter.empty()) it->filters.push_back(filter);
}

bool contains(const std::vector<std::string>& names, const std::string& name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

}  // namespace

bool CatalogOption::applies_to(const std::string& integrator, const std::string& filter) const {
  return contains(integrators, integrator) || contains(filters, filter);
}

std::vector<CatalogOption> option_catalog() {
  std::vector<CatalogOption> out;
  for (const IntegratorEntry& e : integrator_registry().entries())
    for (const OptionSpec& spec : e.schema.options) merge(&out, spec, e.name, "");
  for (const FilterEntry& e : filter_registry().entries())
    for (const OptionSpec& spec : e.schema.options) merge(&out, spec, "", e.name);
  return out;
}

nlohmann::ordered_json option_spec_json(const OptionSpec& s) {
  nlohmann::ordered_json j;
  j["name"] = s.name;
  j["type"] = option_type_name(s.type);
  j["default"] = s.default_text;
  if (s.type == OptionType::integer || s.type == OptionType::real || s.type == OptionType::size) {
    j["min"] = s.min;
    j["max"] = s.max;
  }
  if (s.type == OptionType::choice) j["choices"] = s.choices;
  j["help"] = s.help;
  j["paper"] = s.paper;
  return j;
}

std::vector<CatalogOption> options_of(const std::string& integrator, const std::string& filter) {
  std::vector<CatalogOption> out;
  for (CatalogOption& o : option_catalog())
    if (o.applies_to(integrator, filter)) out.push_back(std::move(o));
  return out;
}

}  // namespace pathspace
