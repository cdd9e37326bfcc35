// The option catalog: every option of every registered integrator and filter, once per name, with
// the entries that define it. The CLI turns it into command-line options and the Python bindings
// into keyword arguments and docstrings, so both come from the registry's one definition.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "pathspace/options/option_spec.h"

namespace pathspace {

struct CatalogOption {
  OptionSpec spec;
  std::vector<std::string> integrators, filters;  // the registry entries that define it, by name

  bool applies_to(const std::string& integrator, const std::string& filter) const;
};

// Sorted as the registry lists its entries (integrators first, then filters; each entry's options in
// its table's order). Throws pathspace::Error when two entries define one name with different
// contracts (type, range, choices, default): options shared by several entries must mean the same.
std::vector<CatalogOption> option_catalog();

// One option as `pathspace info --integrators --json` prints it and Python's pathspace.options()
// returns it: name, type, default, min and max or choices, help, paper.
nlohmann::ordered_json option_spec_json(const OptionSpec& spec);

// The options that `configure_render(integrator, filter, ...)` accepts, in catalog order.
std::vector<CatalogOption> options_of(const std::string& integrator, const std::string& filter);

}  // namespace pathspace
