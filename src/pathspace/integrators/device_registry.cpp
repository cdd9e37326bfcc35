#include "pathspace/integrators/device_registry.h"

#include <algorithm>

#include "pathspace/scene/scene.h"

namespace pathspace {

namespace {

bool listed(const std::vector<std::string>& names, const std::string& name) {
  for (const std::string& n : names)
    if (n == "*" || n == name) return true;
  return false;
}

// Every integrator and filter runs on the CPU; the entry's own factories build them there.
const DeviceRegistrar kCpuRegistrar{DeviceEntry{DeviceEntry::kCpu, "the CPU, every core (--threads)", {"*"}, {"*"}, nullptr, true}};

bool has_media(const Scene& scene) {
  return !scene.media.empty() || std::any_of(scene.materials.begin(), scene.materials.end(),
                                             [](const Material& m) { return m.type == MaterialType::interface; });
}

}  // namespace

bool DeviceEntry::runs_integrator(const std::string& integrator) const { return listed(integrators, integrator); }
bool DeviceEntry::runs_filter(const std::string& filter) const { return filter == FilterChoice::kNone || listed(filters, filter); }

Registry<DeviceEntry>& device_registry() {
  static Registry<DeviceEntry> registry("device");
  return registry;
}

void check_device(const std::string& device, const std::string& integrator, const std::string& filter) {
  const DeviceEntry& d = device_registry().at(device);
  if (!d.runs_integrator(integrator)) {
    std::string runs;
    for (const std::string& n : integrator_registry().names())
      if (d.runs_integrator(n)) runs += (runs.empty() ? "" : ", ") + n;
    throw OptionError("--integrator " + integrator + " does not run on --device " + device + " yet; there: --integrator " +
                      (runs.empty() ? "none" : runs));
  }
  if (!d.runs_filter(filter)) {
    std::string runs;
    for (const std::string& n : filter_registry().names())
      if (d.runs_filter(n)) runs += (runs.empty() ? "" : ", ") + n;
    throw OptionError("--filter " + filter + " does not run on --device " + device + " yet; there: --filter " +
                      (runs.empty() ? "none" : runs));
  }
}

void check_media(const Scene& scene, const std::string& device, const std::string& integrator) {
  if (!has_media(scene)) return;
  if (!integrator_registry().at(integrator).renders_media) {
    std::string renders;
    for (const IntegratorEntry& e : integrator_registry().entries())
      if (e.renders_media) renders += (renders.empty() ? "" : ", ") + e.name;
    throw OptionError("the scene has participating media, which --integrator " + integrator +
                      " does not render yet (docs/media.md); --integrator " + renders + " do");
  }
  if (!device_registry().at(device).renders_media)
    throw OptionError("the scene has participating media, which --device " + device + " does not render yet (docs/media.md)");
}

std::string devices_of_integrator(const std::string& integrator) {
  std::string out;
  for (const DeviceEntry& d : device_registry().entries())
    if (d.runs_integrator(integrator)) out += (out.empty() ? "" : ", ") + d.name;
  return out;
}

}  // namespace pathspace
