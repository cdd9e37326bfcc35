// The runs behind each reproduced PCLT paper figure (study_pclt_figures.h) and the one-line findings
// computed from their numbers. Equal-iteration figures (5-8) use the iteration count PCLT reached in
// fig. 1's time budget, so every figure's images are about as converged as fig. 1's.
#include "study_pclt_figures.h"

#include <algorithm>
#include <bit>

#include <fmt/format.h>

#include "pathspace/base/error.h"

namespace pathspace::cli {

namespace {

using Format = MetricRow::Format;

StudyFigure& figure(std::vector<StudyFigure>* figures, const std::string& id) {
  for (StudyFigure& f : *figures)
    if (f.id == id) return f;
  throw Error("study: no figure " + id);
}

bool has_integrator(const std::string& name) {
  const auto& names = integrator_names();
  return std::find(names.begin(), names.end(), name) != names.end();
}

RunSpec pclt_spec(const std::string& fig, const std::string& label, uint64_t light_paths, uint32_t iterations) {
  RunSpec s;
  s.figure = fig;
  s.label = label;
  s.integrator = "pclt";
  s.settings.pclt.light_paths = light_paths;
  s.iterations = std::max<uint32_t>(1, iterations);
  return s;
}

RunSpec finish(RunSpec s) {
  if (s.integrator == "pclt") s.settings_json = pclt_settings_json(s.settings.pclt);
  if (s.integrator == "sppm") s.settings_json = sppm_settings_json(s.settings.sppm);
  return s;
}

double metric(const StudyRun& r, const char* key) { return r.metrics.contains(key) ? r.metrics[key].get<double>() : 0.0; }

}  // namespace

std::vector<StudyFigure> make_pclt_figures() {
  std::vector<StudyFigure> f(6);
  f[0].id = "fig1";
  f[0].title = "Fig. 1 - equal time: PT, LT, BPT, SPPM, PCLT";
  f[0].paper = "Equal time (1 min) on a diffuse object in a glass container with a mirror. PT misses caustics, LT cannot "
               "project through specular surfaces, BPT has no strategy for SDS paths; only SPPM shows all paths, and PCLT "
               "reaches SPPM's quality with sharper caustics.";
  f[0].method = "Each integrator renders for the same wall-clock budget (whole passes); relMSE is against a long reference "
                "rendered with another seed. BPT appears only when it is registered.";
  f[1].id = "fig5";
  f[1].title = "Fig. 5 - equal iterations: SPPM vs PCLT";
  f[1].paper = "5000 iterations of each with as many eye paths as light paths: PCLT is sharper on diffuse surfaces, "
               "similar in the mirror, and 31% slower (189 s vs 144 s) because of the projection's shadow rays.";
  f[1].method = "SPPM runs as many iterations as PCLT reached in fig. 1 (photons = light paths = pixel count per "
                "iteration); the PCLT column is fig. 1's render.";
  f[2].id = "fig6";
  f[2].title = "Fig. 6 - visibility for projection: shadow ray, z-buffer, plane";
  f[2].paper = "Replacing the projection's shadow ray with a stochastic z-buffer or a plane test (epsilon 5e-4) makes PCLT "
               "as fast as SPPM; the z-buffer loses energy on planar surfaces, the plane test errs slightly at edges.";
  f[2].method = "Fig. 5's iteration count; besides relMSE against the reference, each shortcut is compared with the "
                "shadow-ray image of the same seed (the difference is the shortcut's bias plus little noise).";
  f[2].metric_rows = {{"rel_mse_vs_shadow_ray", "relMSE vs shadow-ray image", Format::number},
                      {"energy_vs_shadow_ray_percent", "energy vs shadow ray", Format::percent}};
  f[3].id = "fig7";
  f[3].title = "Fig. 7 - light paths per iteration: time, memory, error";
  f[3].paper = "Equal light-path count (200 x 2^18, 100 x 2^19, 50 x 2^20): more photons per iteration is faster at "
               "almost the same quality; SPPM's photon map grows with them, PCLT's pixel cache stays at 33 MiB.";
  f[3].method = "PCLT with the plane test (as the paper) and 1/4, 1 and 4 times the pixel count of light paths per "
                "iteration, with 4, 1 and 1/4 times fig. 5's iterations. Memory is the integrator's reported bytes. The "
                "paper's SPPM row is not repeated: pathspace's SPPM stores per-pixel visible points, not photons, so its "
                "memory does not grow with the photon count either.";
  f[3].metric_rows = {{"light_paths_total", "light paths in total", Format::number},
                      {"memory_bytes", "memory", Format::bytes}};
  f[4].id = "fig8";
  f[4].title = "Fig. 8 - full (chained) vs stochastic hash map";
  f[4].paper = "8 iterations: the chained map (33 MiB) against stochastic hash maps of 33, 10 and 1 MiB. Timings are "
               "nearly equal; the stochastic map keeps one pixel per cell neighbourhood, so caustics in the mirror do "
               "not spread over neighbouring pixels, and at 1 MiB collisions start to show.";
  f[4].method = "Fig. 5's iteration count; stochastic tables of 1, 1/8 and 1/64 times the default slot count "
                "(the cache capacity rounded up to a power of two). Eye and light pass times from the integrator.";
  f[4].metric_rows = {{"memory_bytes", "memory", Format::bytes},
                      {"eye_s", "eye pass (all iterations)", Format::seconds},
                      {"light_s", "light pass (all iterations)", Format::seconds},
                      {"gathered_per_iteration", "gathered records / iteration", Format::number}};
  f[5].id = "fig9";
  f[5].title = "Fig. 9 - many lights and distant lights";
  f[5].paper = "A room with 69 lights (BPT 376 s vs PCLT 258 s: light tracing places photons near the lights while "
               "next event estimation is often occluded) and a distant daylight scene (PT 47.5 s vs PCLT 10.9 s, few "
               "photons reach the view), 1000 iterations each.";
  f[5].reproduced = false;
  return f;
}

void describe_fig9(size_t max_builtin_lights, std::vector<StudyFigure>* figures) {
  figure(figures, "fig9").not_reproduced_reason = fmt::format(
      "Not reproduced: pathspace's built-in scenes have at most {} light{} each (SmallVCM's Cornell variants), so there "
      "is no many-light scene, and the sun variant (gbs_s) is a box lit through its open side rather than a distant "
      "daylight scene of the paper's scale.",
      max_builtin_lights, max_builtin_lights == 1 ? "" : "s");
}

void run_pclt_figures(const StudyRunner& runner, const StudyScene& scene, const PcltStudyParams& params,
                      std::vector<StudyFigure>* figures) {
  const uint64_t pixels = uint64_t(scene.scene.camera.width) * uint64_t(scene.scene.camera.height);
  auto add = [&](const RunSpec& spec) { return runner.run(scene, finish(spec)); };

  // Fig. 1: equal time.
  StudyFigure& f1 = figure(figures, "fig1");
  std::vector<std::string> fig1 = {"pt", "lt"};
  if (has_integrator("bpt")) fig1.push_back("bpt");
  fig1.push_back("sppm");
  StudyRun pclt, sppm_t;
  for (const std::string& name : fig1) {
    RunSpec s;
    s.figure = "fig1";
    s.label = name == "pt" ? "PT" : name == "lt" ? "LT" : name == "bpt" ? "BPT" : "SPPM";
    s.integrator = name;
    s.time_s = params.time_s;
    if (name == "sppm") s.settings.sppm.photons = pixels;
    f1.runs.push_back(add(s));
    if (name == "sppm") sppm_t = f1.runs.back();
  }
  RunSpec pclt_t = pclt_spec("fig1", "PCLT", pixels, 1);
  pclt_t.time_s = params.time_s;
  pclt = add(pclt_t);
  f1.runs.push_back(pclt);
  {
    const StudyRun* best = &pclt;
    for (const StudyRun& r : f1.runs)
      if (r.scene_id == scene.id && r.error.rel_mse < best->error.rel_mse) best = &r;
    f1.findings[scene.id] = fmt::format(
        "PCLT relMSE {:.4g} vs SPPM {:.4g} at equal time: PCLT is {} (paper: PCLT better). Lowest relMSE: {} ({:.4g}).",
        pclt.error.rel_mse, sppm_t.error.rel_mse, pclt.error.rel_mse <= sppm_t.error.rel_mse ? "lower or equal" : "higher",
        best->label, best->error.rel_mse);
  }
  const uint32_t n = pclt.iterations;

  // Fig. 5: equal iterations.
  StudyFigure& f5 = figure(figures, "fig5");
  RunSpec sppm_n;
  sppm_n.figure = "fig5";
  sppm_n.label = "SPPM";
  sppm_n.integrator = "sppm";
  sppm_n.settings.sppm.photons = pixels;
  sppm_n.iterations = n;
  const StudyRun sppm = add(sppm_n);
  f5.runs.push_back(sppm);
  f5.runs.push_back(StudyRunner::reuse(pclt, "fig5", "PCLT"));
  f5.findings[scene.id] = fmt::format(
      "{} iterations: PCLT takes {:.2f}x SPPM's time (paper: 1.31x) at relMSE {:.4g} vs SPPM {:.4g}.", n,
      sppm.time_s > 0 ? pclt.time_s / sppm.time_s : 0.0, pclt.error.rel_mse, sppm.error.rel_mse);

  // Fig. 6: visibility shortcuts against the shadow-ray image of the same seed.
  StudyFigure& f6 = figure(figures, "fig6");
  StudyRun shadow = StudyRunner::reuse(pclt, "fig6", "PCLT shadow ray");
  shadow.metrics["rel_mse_vs_shadow_ray"] = 0.0;
  shadow.metrics["energy_vs_shadow_ray_percent"] = 0.0;
  f6.runs.push_back(shadow);
  StudyRun plane;
  std::string finding;
  for (PcltVisibility v : {PcltVisibility::z_buffer, PcltVisibility::plane}) {
    RunSpec s = pclt_spec("fig6", v == PcltVisibility::plane ? "PCLT plane" : "PCLT z-buffer", pixels, n);
    s.settings.pclt.visibility = v;
    StudyRun r = add(s);
    r.metrics["rel_mse_vs_shadow_ray"] = image_error(r.image, pclt.image).rel_mse;
    const double energy = pclt.error.mean_image > 0 ? 100.0 * (r.error.mean_image / pclt.error.mean_image - 1.0) : 0.0;
    r.metrics["energy_vs_shadow_ray_percent"] = energy;
    finding += fmt::format("{}: {:.2f}x the shadow-ray time, energy {:+.1f}%, relMSE {:.4g}. ", r.label,
                           pclt.time_s > 0 ? r.time_s / pclt.time_s : 0.0, energy, r.error.rel_mse);
    f6.runs.push_back(r);
    if (v == PcltVisibility::plane) plane = r;
  }
  f6.findings[scene.id] = finding + fmt::format("Shadow ray: relMSE {:.4g} (paper: z-buffer loses energy on planes, "
                                                "plane test nearly exact and as fast as SPPM).", pclt.error.rel_mse);

  // Fig. 7: equal total light paths, split into fewer or more per iteration (plane test, as the paper).
  StudyFigure& f7 = figure(figures, "fig7");
  finding.clear();
  for (int k : {0, 1, 2}) {
    const uint64_t paths = k == 0 ? std::max<uint64_t>(1, pixels / 4) : k == 1 ? pixels : 4 * pixels;
    const uint32_t iterations = k == 0 ? 4 * n : k == 1 ? n : std::max<uint32_t>(1, (n + 2) / 4);
    StudyRun r;
    if (k == 1) {
      r = StudyRunner::reuse(plane, "fig7", "PCLT 1x pixels");
    } else {
      RunSpec s = pclt_spec("fig7", k == 0 ? "PCLT 0.25x pixels" : "PCLT 4x pixels", paths, iterations);
      s.settings.pclt.visibility = PcltVisibility::plane;
      r = add(s);
    }
    r.metrics["light_paths_total"] = double(paths) * double(r.iterations);
    finding += fmt::format("{}: {:.2f} s, {:.3g} MiB, relMSE {:.4g}. ", r.label, r.time_s,
                           metric(r, "memory_bytes") / (1024.0 * 1024.0), r.error.rel_mse);
    f7.runs.push_back(r);
  }
  f7.findings[scene.id] = finding + "(Paper: more light paths per iteration is faster at similar quality; PCLT's memory "
                                    "does not change.)";

  // Fig. 8: chained map against stochastic maps of shrinking size.
  StudyFigure& f8 = figure(figures, "fig8");
  f8.runs.push_back(StudyRunner::reuse(pclt, "fig8", "Chained (full) map"));
  finding = fmt::format("Chained: {:.2f} s, relMSE {:.4g}. ", pclt.time_s, pclt.error.rel_mse);
  const uint32_t slots = uint32_t(std::bit_ceil(pixels));
  for (uint32_t divisor : {1u, 8u, 64u}) {
    const uint32_t table = std::max<uint32_t>(1, slots / divisor);
    RunSpec s = pclt_spec("fig8", fmt::format("Stochastic map, {} slots", table), pixels, n);
    s.settings.pclt.hash_map = PcltHashMap::stochastic;
    s.settings.pclt.stochastic_slots = table;
    const StudyRun r = add(s);
    finding += fmt::format("{} slots: {:.2f} s, relMSE {:.4g}. ", table, r.time_s, r.error.rel_mse);
    f8.runs.push_back(r);
  }
  f8.findings[scene.id] = finding + "(Paper: equal speed; the stochastic map loses records, visibly at 1 MiB.)";
}

nlohmann::ordered_json to_json(const StudyFigure& f) {
  nlohmann::ordered_json j;
  j["id"] = f.id;
  j["title"] = f.title;
  j["paper"] = f.paper;
  j["reproduced"] = f.reproduced;
  if (f.reproduced) j["method"] = f.method;
  if (!f.reproduced) j["reason"] = f.not_reproduced_reason;
  j["findings"] = f.findings;
  j["runs"] = nlohmann::ordered_json::array();
  for (const StudyRun& r : f.runs) j["runs"].push_back(to_json(r));
  return j;
}

}  // namespace pathspace::cli
