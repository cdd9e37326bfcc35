// The registry of devices a render runs on (`--device`): the CPU, where every integrator and filter
// runs, and backends such as CUDA (gpu/), which name the integrators and filters they run and create
// the integrator themselves. `pathspace info --integrators` lists each integrator's devices from
// here; asking for an integrator or filter a device does not run is a usage error naming those it does.
#pragma once

#include <any>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "pathspace/integrators/integrator_registry.h"
#include "pathspace/options/registry.h"

namespace pathspace {

struct DeviceEntry {
  static constexpr const char* kCpu = "cpu";
  std::string name, description;
  std::vector<std::string> integrators;  // that run on it; {"*"}: all of them
  std::vector<std::string> filters;      // path space filters that run on it; {"*"}: all
  // The integrator `name` on this device, or null where the integrator entry's own factory builds it
  // (the CPU). Throws pathspace::Error when the device is absent ("no CUDA device").
  std::function<std::unique_ptr<Integrator>(const IntegratorContext&, const std::string& integrator, const std::any& settings)> create;
  // Whether its integrators render participating media where their entries do (docs/media.md).
  bool renders_media = false;

  bool runs_integrator(const std::string& integrator) const;
  bool runs_filter(const std::string& filter) const;  // FilterChoice::kNone always
};

Registry<DeviceEntry>& device_registry();

struct DeviceRegistrar {
  explicit DeviceRegistrar(DeviceEntry entry) { device_registry().add(std::move(entry)); }
};

// Throws OptionError unless the device exists and runs the integrator and the filter, naming those it runs.
void check_device(const std::string& device, const std::string& integrator, const std::string& filter);

// Throws Error when the scene has participating media (or surfaces that only bound media) and the
// integrator or the device does not render them, naming those that do.
void check_media(const Scene& scene, const std::string& device, const std::string& integrator);

// The devices an integrator runs on ("cpu, cuda").
std::string devices_of_integrator(const std::string& integrator);

}  // namespace pathspace
