// The equal-time comparisons of `pathspace study psf` (studies/psf/psf_figures.h), which neither path
// space filtering paper has. For each of PsfStudyParams::equal_time_spp: PT + hashed filter (its
// defaults, caustic photons included) for that many passes sets the time that PT and PT + consistent
// filter get (whole passes), and PT followed by the edge-avoiding à-trous filter in screen space
// (studies/psf/atrous_filter.h), whose guide buffers and filtering are timed and added to the PT
// render's time.
#include <chrono>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "pathspace/base/error.h"
#include "studies/psf/atrous_filter.h"
#include "studies/psf/guide_buffers.h"
#include "studies/psf/psf_figures.h"

namespace pathspace::studies {

namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// One equal-time figure: the hashed filter for `spp` passes, then the others for its time.
void run_equal_time_at(const study::FigureRunner& fr, uint32_t spp, std::vector<study::Figure>* figures) {
  study::Figure& f = study::find_figure(figures, equal_time_figure_id(spp));
  const study::PreparedScene& scene = fr.scene();
  study::Measurement hashed = fr.run_one(f.id, pt_with("PT + hashed", "hashed"), study::Budget::for_passes(spp));
  const double budget_s = hashed.time_s;
  std::vector<study::Measurement> runs =
      fr.run(f.id, {pt_with("PT", "none"), pt_with("PT + consistent", "consistent")}, study::Budget::for_seconds(budget_s));
  const study::Measurement& pt = runs.front();
  if (pt.image.size() == 0) throw Error("study psf: the equal-time comparison needs the PT image (RunnerOptions::keep_images)");

  const auto start = std::chrono::steady_clock::now();
  const study::GuideBuffers guides = study::render_guide_buffers(*scene.scene, *scene.accel);
  const double guide_s = seconds_since(start);
  const auto filter_start = std::chrono::steady_clock::now();
  Image filtered = study::atrous_filter(pt.image, guides);
  const double filter_s = seconds_since(filter_start);
  study::Measurement atrous =
      fr.runner().measure_post_process(scene, pt, f.id, "PT + à-trous", std::move(filtered), guide_s + filter_s);
  atrous.filter = "à-trous (screen space)";
  atrous.settings.set("atrous_iterations", study::AtrousSettings{}.iterations);
  atrous.metrics.set("guide_s", guide_s);
  atrous.metrics.set("atrous_s", filter_s);
  // Page order: PT | PT + hashed | the others (the report adds the reference and error maps).
  runs.insert(runs.begin() + 1, std::move(hashed));
  runs.push_back(std::move(atrous));
  f.metric_rows = {{"block_rel_mse", "block relMSE (8×8)", study::MetricFormat::number},
                   {"blotched_share", "blotched blocks (share)", study::MetricFormat::number},
                   {"flip", "FLIP", study::MetricFormat::number},
                   {"guide_s", "guide buffers", study::MetricFormat::seconds},
                   {"atrous_s", "à-trous filter", study::MetricFormat::seconds}};

  const study::Measurement* best = &runs.front();
  std::string list;
  for (const study::Measurement& m : runs) {
    if (m.error.rel_mse < best->error.rel_mse) best = &m;
    list += fmt::format("{}{} {:.4g} ({} spp)", list.empty() ? "" : ", ", m.label, m.error.rel_mse, m.iterations);
  }
  f.findings[scene.id()] = fmt::format("relMSE at {:.3g} s (the hashed filter's {} spp): {}. Lowest: {}.", budget_s, spp,
                                       list, best->label);
  f.runs.insert(f.runs.end(), runs.begin(), runs.end());
}

}  // namespace

void run_equal_time(const study::FigureRunner& fr, const PsfStudyParams& params, std::vector<study::Figure>* figures) {
  for (const uint32_t spp : params.equal_time_spp) run_equal_time_at(fr, spp, figures);
}

}  // namespace pathspace::studies
