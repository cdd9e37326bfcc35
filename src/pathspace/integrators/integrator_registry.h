// The registry of integrators: each integrator registers, with an IntegratorRegistrar in its own
// folder, its name, a one-line description, its options (an OptionTable over its own settings
// struct, with paper sections), the filters it composes with, and a factory. The CLI's --help and
// validation, `pathspace info --integrators [--json]` and the session read this one table.
#pragma once

#include <any>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "pathspace/filters/filter_registry.h"
#include "pathspace/integrators/integrator.h"
#include "pathspace/options/registry.h"
#include "pathspace/options/settings_schema.h"

namespace pathspace {

class Accel;
class Scene;

// What an integrator is built from besides its own settings.
struct IntegratorContext {
  const Scene& scene;
  const Accel& accel;
  uint64_t seed;
  const FilterChoice& filter;  // FilterChoice::kNone unless the entry composes with filters
  // The previous frame's filter (Integrator::carried_filter), taken over instead of a new one.
  std::shared_ptr<PathSpaceFilter> carried_filter = nullptr;
};

struct IntegratorEntry {
  std::string name, description;
  std::string paper;                 // the algorithm and where it is described
  SettingsSchema schema;
  // The filters it composes with (empty: none; kAllFilters: every registered path space filter).
  static constexpr const char* kAllFilters = "*";
  std::vector<std::string> filters;
  // Whether it renders scenes with participating media (docs/media.md); the session refuses such a
  // scene for the others.
  bool renders_media = false;
  std::function<std::unique_ptr<Integrator>(const IntegratorContext&, const std::any&)> create;

  bool composes_with(const std::string& filter) const;
  // The names of the registered filters it composes with.
  std::vector<std::string> filter_names() const;
};

Registry<IntegratorEntry>& integrator_registry();

template <typename Settings>
IntegratorEntry make_integrator_entry(
    std::string name, std::string description, std::string paper, OptionTable<Settings> table, std::vector<std::string> filters,
    std::function<std::unique_ptr<Integrator>(const IntegratorContext&, const Settings&)> create) {
  IntegratorEntry e;
  e.name = std::move(name);
  e.description = std::move(description);
  e.paper = std::move(paper);
  e.schema = SettingsSchema::of(std::move(table));
  e.filters = std::move(filters);
  e.create = [create, owner = e.name](const IntegratorContext& ctx, const std::any& settings) {
    return create(ctx, settings_cast<Settings>(settings, owner));
  };
  return e;
}

// `entry`, marked as rendering participating media.
inline IntegratorEntry with_media(IntegratorEntry entry) {
  entry.renders_media = true;
  return entry;
}

// The factory of an integrator constructed as T(scene, accel, settings, seed).
template <typename T, typename Settings>
std::function<std::unique_ptr<Integrator>(const IntegratorContext&, const Settings&)> construct_with_seed() {
  return [](const IntegratorContext& ctx, const Settings& s) -> std::unique_ptr<Integrator> {
    return std::make_unique<T>(ctx.scene, ctx.accel, s, ctx.seed);
  };
}

// Registers at static initialisation: `const IntegratorRegistrar kRegistrar{make_integrator_entry(...)};`.
// (The integrators library is linked whole-archive, so no registrar is dropped by the linker.)
struct IntegratorRegistrar {
  explicit IntegratorRegistrar(IntegratorEntry entry) { integrator_registry().add(std::move(entry)); }
};

}  // namespace pathspace
