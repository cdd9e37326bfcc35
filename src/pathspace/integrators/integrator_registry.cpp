#include "pathspace/integrators/integrator_registry.h"

#include <algorithm>

namespace pathspace {

bool IntegratorEntry::composes_with(const std::string& filter) const {
  if (filter == FilterChoice::kNone) return true;
  for (const std::string& f : filters)
    if (f == filter || (f == kAllFilters && filter_registry().find(filter))) return true;
  return false;
}

std::vector<std::string> IntegratorEntry::filter_names() const {
  std::vector<std::string> out;
  for (const std::string& name : filter_registry().names())
    if (composes_with(name)) out.push_back(name);
  return out;
}

Registry<IntegratorEntry>& integrator_registry() {
  static Registry<IntegratorEntry> registry("integrator");
  return registry;
}

}  // namespace pathspace
