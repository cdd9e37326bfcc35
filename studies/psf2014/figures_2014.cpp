// Keller, Dahm, Binder 2014 (consistent path space filtering, `--filter consistent`) in
// `pathspace study psf`: figs. 2, 3 and 4 (studies/psf/psf_figures.h), one function each.
#include <string>
#include <vector>

#include <fmt/format.h>

#include "pathspace/options/option_spec.h"
#include "studies/psf/psf_figures.h"

namespace pathspace::studies {

namespace {

using study::Budget;
using study::Measurement;

// Fig. 4's weight settings as --psf-weights values, from uniform weights to the paper's full set
// (sec. 2.1). One list: a setting the consistent filter does not accept in this build is reported
// as missing on the page rather than failing the study.
const std::vector<std::string> kFig4Weights = {"none", "normal", "normal,albedo", "normal,albedo,visibility"};

std::string rel_mse_list(const std::vector<Measurement>& runs) {
  std::string s;
  for (const Measurement& m : runs) s += fmt::format("{}{} {:.4g}", s.empty() ? "" : ", ", m.label, m.error.rel_mse);
  return s;
}

double energy_percent(const Measurement& m) {
  return m.error.mean_reference > 0 ? 100.0 * (m.error.mean_image / m.error.mean_reference - 1.0) : 0.0;
}

}  // namespace

// Fig. 2: iterated averaging at equal paths per pixel.
void run_2014_fig2(const study::FigureRunner& fr, const PsfStudyParams&, std::vector<study::Figure>* figures) {
  study::Figure& f = study::find_figure(figures, "2014-fig2");
  std::vector<study::Configuration> configs = {pt_with("PT", "none")};
  for (int iterations : {1, 2, 4})
    configs.push_back(pt_with(fmt::format("consistent, {} iteration{}", iterations, iterations == 1 ? "" : "s"), "consistent",
                              {{"psf-iterations", std::to_string(iterations)}}));
  const std::vector<Measurement> runs = fr.run(f.id, std::move(configs), Budget::for_passes(4));
  f.runs.insert(f.runs.end(), runs.begin(), runs.end());
  f.findings[fr.scene().id()] = fmt::format(
      "relMSE at 4 paths per pixel: {}. Energy against the reference: PT {:+.1f}%, 4 iterations {:+.1f}% (paper: iterating "
      "smooths more, losing detail).",
      rel_mse_list(runs), energy_percent(runs.front()), energy_percent(runs.back()));
}

// Fig. 3: one progressive render, measured at 1, 4, 16, ... paths per pixel.
void run_2014_fig3(const study::FigureRunner& fr, const PsfStudyParams& params, std::vector<study::Figure>* figures) {
  study::Figure& f = study::find_figure(figures, "2014-fig3");
  std::vector<uint32_t> checkpoints;
  for (uint32_t spp = 1; spp <= params.max_spp; spp *= 4) checkpoints.push_back(spp);
  const std::vector<Measurement> pt = fr.run(f.id, {pt_with("PT", "none")}, Budget::at_passes(checkpoints));
  const std::vector<Measurement> filtered = fr.run(f.id, {pt_with("consistent", "consistent")}, Budget::at_passes(checkpoints));
  f.runs.insert(f.runs.end(), filtered.begin(), filtered.end());
  f.runs.insert(f.runs.end(), pt.begin(), pt.end());
  auto spp = [](const Measurement& m) { return double(m.iterations); };
  study::LinePlot plot;
  plot.title = fmt::format("{}: relMSE against paths per pixel", fr.scene().id());
  plot.x_label = "paths per pixel";
  plot.y_label = "relMSE";
  plot.x_scale = plot.y_scale = study::AxisScale::log;
  plot.series = {rel_mse_series("PT", pt, spp), rel_mse_series("PT + consistent", filtered, spp)};
  f.plots.push_back(study::svg_line_plot(plot));
  bool falling = true;
  for (size_t i = 1; i < filtered.size(); ++i) falling = falling && filtered[i].error.rel_mse < filtered[i - 1].error.rel_mse;
  const Measurement& last = filtered.back();
  f.findings[fr.scene().id()] = fmt::format(
      "Filtered relMSE {} with every checkpoint ({:.4g} at 1 to {:.4g} at {} paths per pixel); PT at {}: {:.4g} (paper: the "
      "filtered image converges, its artefacts are transient).",
      falling ? "falls" : "does not fall", filtered.front().error.rel_mse, last.error.rel_mse, last.iterations, last.iterations,
      pt.back().error.rel_mse);
}

// Fig. 4: the similarity weights at 16 paths per pixel.
void run_2014_fig4(const study::FigureRunner& fr, const PsfStudyParams&, std::vector<study::Figure>* figures) {
  study::Figure& f = study::find_figure(figures, "2014-fig4");
  std::vector<study::Configuration> configs = {pt_with("PT", "none")};
  std::vector<std::string> missing;
  for (const std::string& weights : kFig4Weights) {
    try {
      configs.push_back(pt_with("weights " + weights, "consistent", {{"psf-weights", weights}}));
    } catch (const OptionError&) {
      missing.push_back(weights);
    }
  }
  const std::vector<Measurement> runs = fr.run(f.id, std::move(configs), Budget::for_passes(16));
  f.runs.insert(f.runs.end(), runs.begin(), runs.end());
  std::string sentence = "relMSE at 16 paths per pixel: " + rel_mse_list(runs) + ".";
  for (const std::string& m : missing) sentence += " Not in this build: --psf-weights " + m + ".";
  f.findings[fr.scene().id()] = sentence;
}

// Fig. 7: anti-aliasing by query-only camera paths, on the scene of thin bars (filter-fence).
void run_2014_fig7(const study::FigureRunner& fr, const PsfStudyParams&, std::vector<study::Figure>* figures) {
  study::Figure& f = study::find_figure(figures, "2014-fig7");
  std::vector<Measurement> runs = fr.run(
      f.id,
      {pt_with("PT", "none"), pt_with("consistent", "consistent"),
       pt_with("consistent + 3 query paths", "consistent", {{"psf-aa-paths", "3"}})},
      Budget::for_passes(1));
  const std::vector<Measurement> pt4 = fr.run(f.id, {pt_with("PT, 4 paths per pixel", "none")}, Budget::for_passes(4));
  runs.insert(runs.end(), pt4.begin(), pt4.end());
  f.runs.insert(f.runs.end(), runs.begin(), runs.end());
  f.findings[fr.scene().id()] = fmt::format(
      "relMSE: {}. The query paths lower the filtered error {:.2f}x (paper: anti-aliasing works nicely across discontinuities).",
      rel_mse_list(runs), runs[1].error.rel_mse / runs[2].error.rel_mse);
}

// Sec. 2.3: photon-mapped caustics beside the consistent filter, at equal paths per pixel.
void run_2014_sec23(const study::FigureRunner& fr, const PsfStudyParams&, std::vector<study::Figure>* figures) {
  study::Figure& f = study::find_figure(figures, "2014-sec2.3");
  const std::vector<Measurement> runs = fr.run(
      f.id,
      {pt_with("PT", "none"), pt_with("consistent", "consistent"),
       pt_with("consistent + 1 photon per pixel", "consistent", {{"psf-caustic-photons", "1"}}),
       pt_with("consistent + 4 photons per pixel", "consistent", {{"psf-caustic-photons", "4"}})},
      Budget::for_passes(16));
  f.runs.insert(f.runs.end(), runs.begin(), runs.end());
  f.findings[fr.scene().id()] = fmt::format("relMSE at 16 paths per pixel: {}.", rel_mse_list(runs));
}

}  // namespace pathspace::studies
