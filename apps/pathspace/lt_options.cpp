// CLI options of the light tracer (lt_options.h).
#include "lt_options.h"

#include "usage_error.h"

namespace pathspace::cli {

void add_lt_options(CLI::App* cmd, LtOptions* o) {
  const char* group = "Light tracing (--integrator lt)";
  cmd->add_option("--light-paths", o->light_paths, "Light paths per pass (0: one per pixel)")
      ->check(CLI::Range(uint64_t(0), uint64_t(1) << 32))
      ->capture_default_str()
      ->group(group);
  cmd->add_flag("--lt-skip-emitter", o->skip_emitter, "Do not splat the light sources themselves (SmallVCM's LT)")->group(group);
  cmd->add_option("--lt-filter", o->filter, "Reconstruction filter of the camera projection (PCLT sec. 5.2)")
      ->check(CLI::IsMember({"box", "tent", "gaussian"}))
      ->capture_default_str()
      ->group(group);
  cmd->add_option("--lt-filter-radius", o->filter_radius, "Tent / gaussian radius in pixels")
      ->check(CLI::Range(0.01f, 16.f))
      ->capture_default_str()
      ->group(group);
  cmd->add_option("--lt-splat-scale", o->splat_scale, "Fixed-point units per unit pixel value (0: 2^32)")
      ->check(CLI::Range(0.0, 1e18))
      ->group(group);
}

void apply_lt_options(const LtOptions& o, const std::string& integrator, IntegratorSettings* settings) {
  const bool any = o.light_paths != 0 || o.skip_emitter || o.filter != "box" || o.splat_scale != 0.0;
  if (any && integrator != "lt") throw UsageError("--light-paths and --lt-* options need --integrator lt");
  LtSettings& lt = settings->lt;
  lt.max_segments = settings->pt.max_segments;
  lt.light_paths = o.light_paths;
  lt.skip_emitter = o.skip_emitter;
  lt.filter = o.filter == "tent" ? LtFilter::tent : o.filter == "gaussian" ? LtFilter::gaussian : LtFilter::box;
  lt.filter_radius = o.filter_radius;
  lt.splat_scale = o.splat_scale;
}

}  // namespace pathspace::cli
