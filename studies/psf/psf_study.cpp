// `pathspace study psf` (studies/psf/psf_figures.h): checks the options, runs every figure (or those
// --figures names) on each scene in page order (each scene's reference first), the hash table figures
// and the temporal figures once, and writes the page.
#include <algorithm>
#include <iterator>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "pathspace/options/usage_error.h"

#include "studies/psf/psf_figures.h"
#include "studies/psf/psf_study.h"
#include "studies/common/study_setup.h"

namespace pathspace::studies {

namespace {

using PerSceneFigure = void (*)(const study::FigureRunner&, const PsfStudyParams&, std::vector<study::Figure>*);
// The per-scene figures in page order, each under the id that --figures names it by.
struct PerSceneRun {
  const char* id;
  PerSceneFigure run;
};
constexpr PerSceneRun kPerSceneRuns[] = {
    {"2014-fig2", run_2014_fig2},   {"2014-fig3", run_2014_fig3},     {"2014-fig4", run_2014_fig4},
    {"2014-sec2.3", run_2014_sec23}, {"2021-fig1", run_2021_fig1},   {"2021-fig4", run_2021_fig4},
    {"2021-fig10", run_2021_fig10}, {"equal-time", run_equal_time}};
constexpr std::string_view kEqualTime = "equal-time";

// Whether --figures asks for the figure with this page id (all when the list is empty); "equal-time"
// names every equal-time figure ("equal-time-4spp", ...), and as a run's id it is wanted when any is.
bool wanted(const PsfStudyOptions& psf, std::string_view id) {
  if (psf.figures.empty()) return true;
  for (const std::string& name : psf.figures)
    if (id == name || (name == kEqualTime && id.starts_with(kEqualTime)) || (id == kEqualTime && name.starts_with(kEqualTime)))
      return true;
  return false;
}

// Every name of --figures must be a figure of the page (or "equal-time"): checked before any render.
void check_figure_names(const PsfStudyOptions& psf, const std::vector<study::Figure>& figures) {
  std::string known(kEqualTime);
  for (const study::Figure& f : figures)
    if (!f.id.starts_with(kEqualTime)) known += ", " + f.id;
  for (const std::string& name : psf.figures) {
    const bool found = name == kEqualTime ||
                       std::any_of(figures.begin(), figures.end(), [&](const study::Figure& f) { return f.id == name; });
    if (!found)
      throw UsageError("--figures: unknown figure '" + name + "' (the figures: " + known + ")",
                       "run 'pathspace study psf --help' for the options");
  }
}

}  // namespace

int run_psf_study(const StudyOptions& o, const PsfStudyOptions& psf_given) {
  PsfStudyOptions psf = psf_given;
  std::vector<study::Figure> figures = make_psf_figures(psf.equal_time_spp);
  check_figure_names(psf, figures);
  // The temporal figures share their runs: the orbit and fig. 9 the frames, sec. 3.4.3 the flight.
  if (!wanted(psf, "2021-sec3.4.1") && !wanted(psf, "2021-fig9")) psf.temporal_frames = 0;
  if (!wanted(psf, "2021-sec3.4.3")) psf.eviction_frames = 0;
  int vertex_width = 0, vertex_height = 0;
  parse_resolution(psf.vertex_set_resolution, "--vertex-set-resolution", &vertex_width, &vertex_height);
  const std::string room_scene = psf.temporal_frames > 0 || psf.eviction_frames > 0 ? resolve_room_scene(psf.room_scene) : psf.room_scene;
  const StudySetup setup = prepare_study(o);
  // The equal-time comparison filters the PT image after the render, so images are kept until each
  // scene is done.
  const study::ExperimentRunner runner = make_study_runner(o, /*keep_images=*/true);
  StudyDocument doc = study_document(
      o, setup, "psf",
      "Path Space Filtering (Keller, Dahm, Binder 2014); Massively Parallel Path Space Filtering (Binder, Fricke, Keller 2021)",
      "Path space filtering: the papers' figures on pathspace scenes");
  doc.settings["max_spp"] = psf.max_spp;
  doc.settings["vertex_set_resolution"] = psf.vertex_set_resolution;
  doc.settings["temporal_frames"] = psf.temporal_frames;
  doc.settings["eviction_frames"] = psf.eviction_frames;
  doc.settings["equal_time_spp"] = psf.equal_time_spp;
  doc.settings["figures"] = psf.figures;
  doc.figures = std::move(figures);
  const PsfStudyParams params{o.seed, psf.max_spp, psf.equal_time_spp};
  // Each scene's reference costs time: none is made when no per-scene figure is asked for.
  const bool per_scene = std::any_of(std::begin(kPerSceneRuns), std::end(kPerSceneRuns),
                                     [&](const PerSceneRun& r) { return wanted(psf, r.id); });
  if (per_scene)
    for (const std::string& name : setup.scene_names) {
      // One scene at a time: its geometry, acceleration structure and images are freed before the next.
      const study::PreparedScene scene =
          runner.prepare(study::SceneSpec{name, setup.width, setup.height}, study_reference(o, setup, name));
      const study::FigureRunner fr(runner, scene, o.seed);
      for (const PerSceneRun& r : kPerSceneRuns)
        if (wanted(psf, r.id)) r.run(fr, params, &doc.figures);
      for (study::Figure& f : doc.figures)
        for (study::Measurement& m : f.runs) m.image = Image();
      doc.scenes.push_back(scene.summary);
    }
  if (wanted(psf, "2014-fig7")) {
    // 2014 fig. 7 needs thin geometry: the built-in fence, with a reference of its own.
    const study::PreparedScene fence = runner.prepare(study::SceneSpec{"filter-fence", setup.width, setup.height},
                                                      study_reference(o, setup, "filter-fence"));
    run_2014_fig7(study::FigureRunner(runner, fence, o.seed), params, &doc.figures);
    for (study::Measurement& m : study::find_figure(&doc.figures, "2014-fig7").runs) m.image = Image();
    doc.scenes.push_back(fence.summary);
  }
  if (wanted(psf, "2019-fig7") || wanted(psf, "2019-fig8"))
    run_hash_table_figures(vertex_width, vertex_height, o.threads, o.quiet, &doc.figures);
  // The hashed filter across frames (2021 sec. 3.4): its own scenes and frames, once.
  if (psf.temporal_frames > 0 || psf.eviction_frames > 0)
    run_temporal_figures(runner,
                         TemporalStudyParams{setup.width, setup.height, o.seed, setup.reference_time_s, psf.temporal_frames,
                                             psf.eviction_frames, room_scene},
                         &doc.figures, &doc.scenes);
  // Dropped only now: the hash table and temporal runs fill their figures in pairs and threes.
  std::erase_if(doc.figures, [&](const study::Figure& f) { return !wanted(psf, f.id); });
  write_study(o, doc);
  return 0;
}

}  // namespace pathspace::studies
