// RenderConfig: what a RenderSession renders with: an integrator and its settings, the path space
// filter and its settings, the seed, the thread count and the device. Built either in code from the typed
// settings structs (make_render_config) or from options given by name, as the CLI and the Python
// bindings receive them (configure_render), which checks every option against the registry.
#pragma once

#include <any>
#include <cstdint>
#include <string>

#include "pathspace/filters/filter_registry.h"
#include "pathspace/integrators/device_registry.h"
#include "pathspace/integrators/integrator_registry.h"
#include "pathspace/options/option_values.h"

namespace pathspace {

struct RenderConfig {
  std::string integrator = "pt";
  std::any settings;    // the integrator's settings struct (PtSettings, ...); empty: its defaults
  FilterChoice filter;  // FilterChoice::kNone: no path space filter
  uint64_t seed = 0;
  int threads = 0;      // <= 0: all cores
  std::string device = DeviceEntry::kCpu;  // where the passes run (integrators/device_registry.h)
};

// A config from typed settings: make_render_config("sppm", SppmSettings{...}, seed).
template <typename Settings>
RenderConfig make_render_config(std::string integrator, Settings settings, uint64_t seed = 0) {
  RenderConfig c;
  c.integrator = std::move(integrator);
  c.settings = std::move(settings);
  c.seed = seed;
  return c;
}

// The same with a filter: with_filter(config, "hashed", HashedFilterSettings{...}).
template <typename FilterSettings>
RenderConfig with_filter(RenderConfig config, std::string filter, FilterSettings settings) {
  config.filter.name = std::move(filter);
  config.filter.settings = std::move(settings);
  return config;
}

// A config from options given by name (without dashes). Throws OptionError when the integrator or
// filter is unknown, the filter does not compose with the integrator, an option belongs to neither
// (naming the integrators or filters it does belong to), or a value is out of range.
RenderConfig configure_render(const std::string& integrator, const std::string& filter, const OptionValues& given);

// configure_render's config run with `seed`, `threads` and `device`, which must run the integrator
// and the filter (check_device). Throws OptionError. What the CLI, the viewer and Python render with.
RenderConfig configure_run(const std::string& integrator, const std::string& filter, const OptionValues& given, uint64_t seed,
                           int threads, const std::string& device);

// Throws OptionError unless the integrator exists and composes with the filter.
void check_composition(const std::string& integrator, const std::string& filter);

}  // namespace pathspace
