// `--integrator bpt`: the options of bidirectional path tracing and its registration.
#include "pathspace/integrators/bpt/bpt_integrator.h"
#include "pathspace/integrators/common/common_options.h"
#include "pathspace/integrators/integrator_registry.h"

namespace pathspace {

namespace {

OptionTable<BptSettings> bpt_options() {
  using S = BptSettings;
  OptionTable<S> t;
  add_max_depth_option(t, &S::max_segments);
  add_mis_option(t, &S::mis);
  t.number("bpt-strategy-images", &S::strategy_images, 0, 32,
           "Also write one MIS-weighted image per strategy (s, t) for path lengths up to N segments, as "
           "OUT.aov-bpt-sS-tT.exr (they sum to the image)");
  t.number("bpt-splat-scale", &S::splat_scale, 0.0, 1e18, "Fixed-point units per unit pixel value of t = 1 splats")
      .shows_default("2^32");
  return t;
}

const IntegratorRegistrar kRegistrar{with_media(make_integrator_entry<BptSettings>(
    "bpt", "bidirectional path tracing, every strategy (s, t) weighted by MIS",
    "Veach 1997, ch. 10; MIS as in the VCM technical report (Georgiev et al. 2012)", bpt_options(), {},
    construct_with_seed<BptIntegrator, BptSettings>()))};

}  // namespace

}  // namespace pathspace
