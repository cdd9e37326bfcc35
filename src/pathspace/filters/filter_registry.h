// The registry of path space filters: each filter registers its name, a one-line description, its
// options (an OptionTable over its settings struct) and a factory, with a FilterRegistrar in its own
// source file. Integrators that filter (pt) create the chosen filter through make_filter().
#pragma once

#include <any>
#include <functional>
#include <memory>
#include <string>

#include "pathspace/camera/perspective_camera.h"
#include "pathspace/filters/path_space_filter.h"
#include "pathspace/options/registry.h"
#include "pathspace/options/settings_schema.h"

namespace pathspace {

// The chosen filter and its settings (the filter's own settings struct; empty = its defaults).
struct FilterChoice {
  static constexpr const char* kNone = "none";
  std::string name = kNone;
  std::any settings;
  bool active() const { return name != kNone; }
};

// What a filter is built for: the image it filters.
struct FilterContext {
  const PerspectiveCamera& camera;
  size_t pixels;
};

struct FilterEntry {
  std::string name, description;
  std::string paper;  // the paper and sections it implements
  SettingsSchema schema;
  std::function<std::unique_ptr<PathSpaceFilter>(const FilterContext&, const std::any&)> create;
};

Registry<FilterEntry>& filter_registry();

// A filter entry from a typed options table and factory.
template <typename Settings>
FilterEntry make_filter_entry(std::string name, std::string description, std::string paper, OptionTable<Settings> table,
                              std::function<std::unique_ptr<PathSpaceFilter>(const FilterContext&, const Settings&)> create) {
  FilterEntry e;
  e.name = std::move(name);
  e.description = std::move(description);
  e.paper = std::move(paper);
  e.schema = SettingsSchema::of(std::move(table));
  e.create = [create, owner = e.name](const FilterContext& ctx, const std::any& settings) {
    return create(ctx, settings_cast<Settings>(settings, owner));
  };
  return e;
}

// Registers at static initialisation: `const FilterRegistrar kRegistrar{make_filter_entry(...)};`.
struct FilterRegistrar {
  explicit FilterRegistrar(FilterEntry entry) { filter_registry().add(std::move(entry)); }
};

// Null for FilterChoice::kNone; throws OptionError for an unknown name.
std::unique_ptr<PathSpaceFilter> make_filter(const FilterChoice& choice, const FilterContext& context);

}  // namespace pathspace
