// CLI options of pixel cache light tracing (pclt_options.h).
#include "pclt_options.h"

#include <bit>

#include "usage_error.h"

namespace pathspace::cli {

void add_pclt_options(CLI::App* cmd, PcltOptions* o) {
  const char* group = "Pixel cache light tracing (--integrator pclt)";
  cmd->add_option("--pclt-light-paths", o->light_paths, "Light paths per iteration (0: one per pixel)")
      ->check(CLI::Range(uint64_t(0), uint64_t(1) << 32))
      ->capture_default_str()
      ->group(group);
  cmd->add_option("--pclt-alpha", o->alpha, "Knaus-Zwicker radius reduction (eq. 1); the paper recommends [1/3, 2/3]")
      ->check(CLI::Range(1e-3f, 1.f))
      ->capture_default_str()
      ->group(group);
  cmd->add_option("--pclt-radius", o->radius, "Initial gathering radius in scene units (0: 1% of the scene's bounding radius)")
      ->check(CLI::Range(0.f, 1e30f))
      ->capture_default_str()
      ->group(group);
  cmd->add_option("--pclt-filter", o->filter, "Reconstruction filter of the camera projection (sec. 5.2)")
      ->check(CLI::IsMember({"box", "tent", "gaussian"}))
      ->capture_default_str()
      ->group(group);
  cmd->add_option("--pclt-filter-radius", o->filter_radius, "Tent / gaussian radius in pixels")
      ->check(CLI::Range(0.01f, 16.f))
      ->capture_default_str()
      ->group(group);
  cmd->add_option("--pclt-visibility", o->visibility,
                  "Projection visibility: shadow ray (unbiased), stochastic z-buffer or plane test (sec. 5.3, biased)")
      ->check(CLI::IsMember({"shadow-ray", "z-buffer", "plane"}))
      ->capture_default_str()
      ->group(group);
  cmd->add_option("--pclt-epsilon", o->epsilon, "z-buffer / plane tolerance, relative to the view depth")
      ->check(CLI::Range(0.f, 0.5f))
      ->capture_default_str()
      ->group(group);
  cmd->add_flag("--pclt-no-specular-emission", o->no_specular_emission,
                "Do not add emission seen through specular/glossy eye bounces (ES+L), as in the paper")
      ->group(group);
  cmd->add_option("--pclt-hash-map", o->hash_map, "Pixel cache search structure (sec. 4, fig. 8)")
      ->check(CLI::IsMember({"chained", "stochastic"}))
      ->capture_default_str()
      ->group(group);
  cmd->add_option("--pclt-stochastic-slots", o->stochastic_slots,
                  "Stochastic hash map table size, a power of two (0: the cache capacity rounded up)")
      ->check(CLI::Range(0u, 1u << 31))
      ->group(group);
  cmd->add_option("--pclt-cache-capacity", o->cache_capacity, "Pixel cache records per iteration (0: the pixel count)")
      ->check(CLI::Range(uint64_t(0), uint64_t(1) << 31))
      ->group(group);
  cmd->add_flag("--pclt-stochastic-store", o->stochastic_store,
                "When the cache is full, keep a uniform random subset and reweight (unbiased) instead of dropping")
      ->group(group);
}

void apply_pclt_options(const PcltOptions& o, const std::string& integrator, IntegratorSettings* settings) {
  const PcltOptions defaults;
  const bool any = o.light_paths != defaults.light_paths || o.alpha != defaults.alpha || o.radius != defaults.radius ||
                   o.filter != defaults.filter || o.filter_radius != defaults.filter_radius || o.visibility != defaults.visibility ||
                   o.epsilon != defaults.epsilon || o.no_specular_emission || o.hash_map != defaults.hash_map ||
                   o.stochastic_slots != 0 || o.cache_capacity != 0 || o.stochastic_store;
  if (any && integrator != "pclt") throw UsageError("--pclt-* options need --integrator pclt");
  if (o.stochastic_slots != 0 && !std::has_single_bit(o.stochastic_slots))
    throw UsageError("--pclt-stochastic-slots must be a power of two");
  if (o.stochastic_slots != 0 && o.hash_map != "stochastic") throw UsageError("--pclt-stochastic-slots needs --pclt-hash-map stochastic");
  PcltSettings& s = settings->pclt;
  s.max_segments = settings->pt.max_segments;
  s.light_paths = o.light_paths;
  s.alpha = o.alpha;
  s.initial_radius = o.radius;
  s.filter = o.filter == "tent" ? LtFilter::tent : o.filter == "gaussian" ? LtFilter::gaussian : LtFilter::box;
  s.filter_radius = o.filter_radius;
  s.visibility = o.visibility == "z-buffer" ? PcltVisibility::z_buffer
                 : o.visibility == "plane"  ? PcltVisibility::plane
                                            : PcltVisibility::shadow_ray;
  s.epsilon = o.epsilon;
  s.specular_emission = !o.no_specular_emission;
  s.hash_map = o.hash_map == "stochastic" ? PcltHashMap::stochastic : PcltHashMap::chained;
  s.stochastic_slots = o.stochastic_slots;
  s.cache_capacity = o.cache_capacity;
  s.stochastic_store = o.stochastic_store;
}

}  // namespace pathspace::cli
