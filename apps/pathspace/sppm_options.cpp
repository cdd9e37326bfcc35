// CLI options of stochastic progressive photon mapping (sppm_options.h).
#include "sppm_options.h"

#include "usage_error.h"

namespace pathspace::cli {

void add_sppm_options(CLI::App* cmd, SppmOptions* o) {
  const char* group = "Photon mapping (--integrator sppm)";
  cmd->add_option("--photons", o->photons, "Photons per iteration (0: one per pixel)")
      ->check(CLI::Range(uint64_t(0), uint64_t(1) << 32))
      ->capture_default_str()
      ->group(group);
  cmd->add_option("--sppm-alpha", o->alpha, "Knaus-Zwicker radius reduction: r_{i+1} = r_i sqrt((i + alpha) / (i + 1))")
      ->check(CLI::Range(1e-3f, 1.f))
      ->capture_default_str()
      ->group(group);
  cmd->add_option("--sppm-radius", o->radius, "Initial gathering radius in scene units (0: 1% of the scene's bounding radius)")
      ->check(CLI::Range(0.f, 1e30f))
      ->capture_default_str()
      ->group(group);
  cmd->add_option("--sppm-glossy-roughness", o->glossy_roughness,
                  "Camera paths pass through purely glossy vertices smoother than this (0: stop at the first non-delta vertex)")
      ->check(CLI::Range(0.f, 1.f))
      ->capture_default_str()
      ->group(group);
}

void apply_sppm_options(const SppmOptions& o, const std::string& integrator, IntegratorSettings* settings) {
  const bool any = o.photons != 0 || o.alpha != 2.f / 3.f || o.radius != 0.f || o.glossy_roughness != 0.f;
  if (any && integrator != "sppm") throw UsageError("--photons and --sppm-* options need --integrator sppm");
  SppmSettings& s = settings->sppm;
  s.max_segments = settings->pt.max_segments;
  s.photons = o.photons;
  s.alpha = o.alpha;
  s.initial_radius = o.radius;
  s.glossy_roughness = o.glossy_roughness;
}

}  // namespace pathspace::cli
