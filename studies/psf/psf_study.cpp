// `pathspace study psf` (studies/psf/psf_figures.h): checks the options, runs every figure on each scene in
// page order (each scene's reference first), the hash table figures and the temporal figures once,
// and writes the page.
#include <fmt/format.h>

#include "studies/psf/psf_figures.h"
#include "studies/psf/psf_study.h"
#include "studies/common/study_setup.h"

namespace pathspace::studies {

int run_psf_study(const StudyOptions& o, const PsfStudyOptions& psf) {
  int vertex_width = 0, vertex_height = 0;
  parse_resolution(psf.vertex_set_resolution, "--vertex-set-resolution", &vertex_width, &vertex_height);
  const std::string room_scene = psf.temporal_frames > 0 || psf.eviction_frames > 0 ? resolve_room_scene(psf.room_scene) : psf.room_scene;
  const StudySetup setup = prepare_study(o);
  // The equal-time comparison filters the PT image after the render, so images are kept until each
  // scene is done.
  const study::ExperimentRunner runner = make_study_runner(o, /*keep_images=*/true);
  const study::ReferenceSpec reference = study_reference(o, setup);
  StudyDocument doc = study_document(
      o, setup, "psf",
      "Path Space Filtering (Keller, Dahm, Binder 2014); Massively Parallel Path Space Filtering (Binder, Fricke, Keller 2021)",
      "Path space filtering: the papers' figures on pathspace scenes");
  doc.settings["max_spp"] = psf.max_spp;
  doc.settings["vertex_set_resolution"] = psf.vertex_set_resolution;
  doc.settings["temporal_frames"] = psf.temporal_frames;
  doc.settings["eviction_frames"] = psf.eviction_frames;
  doc.settings["equal_time_spp"] = psf.equal_time_spp;
  doc.figures = make_psf_figures(psf.equal_time_spp);
  const PsfStudyParams params{o.seed, psf.max_spp, psf.equal_time_spp};
  for (const std::string& name : setup.scene_names) {
    // One scene at a time: its geometry, acceleration structure and images are freed before the next.
    const study::PreparedScene scene = runner.prepare(study::SceneSpec{name, setup.width, setup.height}, reference);
    const study::FigureRunner fr(runner, scene, o.seed);
    for (auto run : {run_2014_fig2, run_2014_fig3, run_2014_fig4, run_2014_sec23, run_2021_fig1, run_2021_fig4, run_2021_fig10,
                     run_equal_time})
      run(fr, params, &doc.figures);
    for (study::Figure& f : doc.figures)
      for (study::Measurement& m : f.runs) m.image = Image();
    doc.scenes.push_back(scene.summary);
  }
  {
    // 2014 fig. 7 needs thin geometry: the built-in fence, with a reference of its own.
    const study::PreparedScene fence = runner.prepare(study::SceneSpec{"filter-fence", setup.width, setup.height}, reference);
    run_2014_fig7(study::FigureRunner(runner, fence, o.seed), params, &doc.figures);
    for (study::Measurement& m : study::find_figure(&doc.figures, "2014-fig7").runs) m.image = Image();
    doc.scenes.push_back(fence.summary);
  }
  run_hash_table_figures(vertex_width, vertex_height, o.threads, o.quiet, &doc.figures);
  // The hashed filter across frames (2021 sec. 3.4): its own scenes and frames, once.
  run_temporal_figures(runner,
                       TemporalStudyParams{setup.width, setup.height, o.seed, setup.reference_time_s, psf.temporal_frames,
                                           psf.eviction_frames, room_scene},
                       &doc.figures, &doc.scenes);
  write_study(o, doc);
  return 0;
}

}  // namespace pathspace::studies
