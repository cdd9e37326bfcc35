// `--integrator pclt`: the options of pixel cache light tracing (Jendersie et al. 2017; section
// numbers are the PCLT paper's) and its registration.
#include <bit>

#include "pathspace/integrators/common/common_options.h"
#include "pathspace/integrators/integrator_registry.h"
#include "pathspace/integrators/pclt/pclt_integrator.h"

namespace pathspace {

namespace {

OptionTable<PcltSettings> pclt_options() {
  using S = PcltSettings;
  OptionTable<S> t;
  add_max_depth_option(t, &S::max_segments);
  t.number("pclt-light-paths", &S::light_paths, 0, double(uint64_t(1) << 32), "Light paths per iteration")
      .shows_default("one per pixel");
  t.number("pclt-alpha", &S::alpha, 1e-3, 1.0, "Knaus-Zwicker radius reduction; the paper recommends [1/3, 2/3]", "eq. 1");
  t.number("pclt-radius", &S::initial_radius, 0.0, 1e30, "Initial gathering radius in scene units")
      .shows_default("1% of the scene's bounding radius");
  t.choice("pclt-visibility", &S::visibility,
           std::vector<std::pair<std::string, PcltVisibility>>{{"shadow-ray", PcltVisibility::shadow_ray},
                                                               {"z-buffer", PcltVisibility::z_buffer},
                                                               {"plane", PcltVisibility::plane}},
           "Projection visibility: shadow ray (unbiased), stochastic z-buffer or plane test (biased)", "sec. 5.3");
  t.number("pclt-epsilon", &S::epsilon, 0.0, 0.5, "z-buffer / plane tolerance, relative to the view depth", "sec. 5.3");
  t.flag("pclt-no-specular-emission", &S::specular_emission, false,
         "Do not add emission seen through specular/glossy eye bounces (ES+L), as in the paper");
  t.choice("pclt-hash-map", &S::hash_map,
           std::vector<std::pair<std::string, PcltHashMap>>{{"chained", PcltHashMap::chained}, {"stochastic", PcltHashMap::stochastic}},
           "Pixel cache search structure", "sec. 4, fig. 8");
  t.number("pclt-stochastic-slots", &S::stochastic_slots, 0, double(1u << 31), "Stochastic hash map table size, a power of two")
      .shows_default("the cache capacity rounded up");
  t.number("pclt-cache-capacity", &S::cache_capacity, 0, double(uint64_t(1) << 31), "Pixel cache records per iteration")
      .shows_default("the pixel count");
  t.flag("pclt-stochastic-store", &S::stochastic_store, true,
         "When the cache is full, keep a uniform random subset and reweight (unbiased) instead of dropping", "sec. 6");
  t.check([](const S& s) {
    if (s.stochastic_slots != 0 && !std::has_single_bit(s.stochastic_slots))
      throw OptionError("--pclt-stochastic-slots must be a power of two");
    if (s.stochastic_slots != 0 && s.hash_map != PcltHashMap::stochastic)
      throw OptionError("--pclt-stochastic-slots needs --pclt-hash-map stochastic");
  });
  return t;
}

const IntegratorRegistrar kRegistrar{make_integrator_entry<PcltSettings>(
    "pclt", "pixel cache light tracing: eye pass into a pixel cache, light paths gather from it and project to the camera",
    "Jendersie, Kuri, Grosch 2017, sec. 3-5", pclt_options(), {},
    construct_with_seed<PcltIntegrator, PcltSettings>())};

}  // namespace

}  // namespace pathspace
