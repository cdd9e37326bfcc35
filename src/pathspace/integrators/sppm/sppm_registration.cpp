// `--integrator sppm`: the options of stochastic progressive photon mapping and its registration.
#include "pathspace/integrators/common/common_options.h"
#include "pathspace/integrators/integrator_registry.h"
#include "pathspace/integrators/sppm/sppm_integrator.h"

namespace pathspace {

namespace {

OptionTable<SppmSettings> sppm_options() {
  using S = SppmSettings;
  OptionTable<S> t;
  add_max_depth_option(t, &S::max_segments);
  t.number("photons", &S::photons, 0, double(uint64_t(1) << 32), "Photons per iteration").shows_default("one per pixel");
  t.number("sppm-alpha", &S::alpha, 1e-3, 1.0, "Knaus-Zwicker radius reduction: r_{i+1} = r_i sqrt((i + alpha) / (i + 1))",
           "PCLT paper eq. 1 (Knaus and Zwicker 2011)");
  t.number("sppm-radius", &S::initial_radius, 0.0, 1e30, "Initial gathering radius in scene units")
      .shows_default("1% of the scene's bounding radius");
  t.number("sppm-glossy-roughness", &S::glossy_roughness, 0.0, 1.0,
           "Camera paths pass through purely glossy vertices smoother than this (0: stop at the first non-delta vertex)");
  return t;
}

const IntegratorRegistrar kRegistrar{make_integrator_entry<SppmSettings>(
    "sppm", "stochastic progressive photon mapping with the Knaus-Zwicker global radius update",
    "Hachisuka and Jensen 2009; radius: Knaus and Zwicker 2011 (PCLT paper eq. 1)", sppm_options(), {},
    construct_with_seed<SppmIntegrator, SppmSettings>())};

}  // namespace

}  // namespace pathspace
