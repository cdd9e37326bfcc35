// Name -> integrator factory. New integrators (lt, bpt, sppm, pclt) register here.
#include <fmt/format.h>

#include "pathspace/base/error.h"
#include "pathspace/integrators/bpt/bpt_integrator.h"
#include "pathspace/integrators/integrator.h"
#include "pathspace/integrators/lt/lt_integrator.h"
#include "pathspace/integrators/pclt/pclt_integrator.h"
#include "pathspace/integrators/pt/pt_integrator.h"
#include "pathspace/integrators/sppm/sppm_integrator.h"

namespace pathspace {

const std::vector<std::string>& integrator_names() {
  static const std::vector<std::string> names = {"pt", "lt", "sppm", "pclt", "bpt"};
  return names;
}

std::unique_ptr<Integrator> make_integrator(const std::string& name, const Scene& scene, const Accel& accel,
                                            const IntegratorSettings& settings) {
  if (name == "pt") return std::make_unique<PtIntegrator>(scene, accel, settings);
  if (name == "lt") return std::make_unique<LtIntegrator>(scene, accel, settings);
  if (name == "sppm") return std::make_unique<SppmIntegrator>(scene, accel, settings);
  if (name == "bpt") return std::make_unique<BptIntegrator>(scene, accel, settings);
  if (name == "pclt") return std::make_unique<PcltIntegrator>(scene, accel, settings);
  throw Error(fmt::format("unknown integrator '{}' (available: {})", name, fmt::join(integrator_names(), ", ")));
}

}  // namespace pathspace
