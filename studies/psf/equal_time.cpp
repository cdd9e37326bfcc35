// The equal-time comparison of `pathspace study psf` (studies/psf/psf_figures.h), which neither path space
// filtering paper has: PT, PT + hashed, PT + consistent filter (with and without photon-mapped
// caustics, one photon per pixel and pass) for the same wall time, and PT
// followed by the edge-avoiding à-trous filter in screen space (studies/psf/atrous_filter.h), whose guide
// buffers and filtering are timed and added to the PT render's time.
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

}  // namespace

void run_equal_time(const study::FigureRunner& fr, const PsfStudyParams& params, std::vector<study::Figure>* figures) {
  study::Figure& f = study::find_figure(figures, "equal-time");
  const study::PreparedScene& scene = fr.scene();
  std::vector<study::Measurement> runs =
      fr.run(f.id,
             {pt_with("PT", "none"), pt_with("PT + hashed", "hashed"), pt_with("PT + consistent", "consistent"),
              pt_with("PT + consistent + caustic photons", "consistent", {{"psf-caustic-photons", "1"}})},
             study::Budget::for_seconds(params.time_s));
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
  f.findings[scene.id()] = fmt::format("relMSE at {:.3g} s: {}. Lowest: {}.", params.time_s, list, best->label);
  f.runs.insert(f.runs.end(), runs.begin(), runs.end());
}

}  // namespace pathspace::studies
