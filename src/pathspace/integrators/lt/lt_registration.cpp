// `--integrator lt`: the options of light tracing and its registration.
#include "pathspace/integrators/common/common_options.h"
#include "pathspace/integrators/integrator_registry.h"
#include "pathspace/integrators/lt/lt_integrator.h"

namespace pathspace {

namespace {

OptionTable<LtSettings> lt_options() {
  using S = LtSettings;
  OptionTable<S> t;
  add_max_depth_option(t, &S::max_segments);
  t.number("light-paths", &S::light_paths, 0, double(uint64_t(1) << 32), "Light paths per pass").shows_default("one per pixel");
  t.flag("lt-skip-emitter", &S::skip_emitter, true, "Do not splat the light sources themselves (SmallVCM's LT)");
  t.number("lt-splat-scale", &S::splat_scale, 0.0, 1e18, "Fixed-point units per unit pixel value").shows_default("2^32");
  return t;
}

const IntegratorRegistrar kRegistrar{with_media(make_integrator_entry<LtSettings>(
    "lt", "light tracing: light paths connected to the camera and splatted (fixed-point, deterministic)",
    "Veach 1997, ch. 10 (the t = 1 strategies); camera projection: PCLT paper sec. 5.2", lt_options(), {},
    construct_with_seed<LtIntegrator, LtSettings>()))};

}  // namespace

}  // namespace pathspace
