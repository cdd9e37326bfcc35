// `pathspace study` (study_command.h): the subcommands' options; the studies themselves live in
// studies/ (one folder per paper), which this file only dispatches to.
#include "study_command.h"

#include <fmt/format.h>

#include "number_options.h"
#include "pathspace/base/error.h"
#include "pathspace/session/run_options.h"
#if PATHSPACE_HAVE_STUDIES
#include "studies/gallery/gallery.h"
#include "studies/pclt/pclt_study.h"
#include "studies/psf/psf_study.h"
#endif

namespace pathspace::cli {

namespace {

void add_common_options(CLI::App* sub, studies::StudyOptions* o, const std::string& time_help) {
  sub->add_option("-o,--out", o->out, "Output folder (created)")->capture_default_str();
  sub->add_option("-r,--resolution", o->resolution, "Image size WxH")->capture_default_str();
  sub->add_option("-t,--time", o->time_s, time_help)->check(checked_real("time", 1e-3, 1e6))->capture_default_str();
  sub->add_option("--reference-time", o->reference_time_s, "Seconds for each scene's reference (default: 20 x --time)")
      ->check(checked_real("reference-time", 1e-3, 1e7));
  sub->add_option("--reference-dir", o->reference_dir,
                  "Folder of references made elsewhere: a scene whose <name>.exr is there reads it (and <name>.variance.exr) "
                  "instead of rendering one");
  sub->add_option("--scenes", o->scenes, "Built-in scenes, comma-separated names or ids")->delimiter(',')->capture_default_str();
  sub->add_option("--seed", o->seed, "Random seed of the runs (the reference uses another)")
      ->check(seed_check())
      ->capture_default_str();
  sub->add_option("-j,--threads", o->threads, "Worker threads (0: all cores)")->check(threads_check())->capture_default_str();
  sub->add_flag("--no-exr", o->no_exr, "Write PNG only (commit-sized output)");
  sub->add_flag("-q,--quiet", o->quiet, "No progress lines");
}

void add_gallery_options(CLI::App* g, studies::GalleryOptions* o) {
  g->add_option("dir", o->dir, "Folder of scenes: itself and each subfolder holding TungstenRender.exr and a scene file")->required();
  g->add_option("-o,--out", o->out, "Output folder (created)")->capture_default_str();
  g->add_option("-t,--time", o->time_s, "Seconds of rendering per scene")->check(checked_real("time", 1e-3, 1e6))->capture_default_str();
  g->add_option("-i,--integrator", o->integrator, "Integrator of the renders")->capture_default_str();
  g->add_option("--seed", o->seed, "Random seed")->check(seed_check())->capture_default_str();
  g->add_option("-j,--threads", o->threads, "Worker threads (0: all cores)")->check(threads_check())->capture_default_str();
  g->add_flag("--substitute-missing-textures", o->substitute_missing_textures,
              "Render scenes with missing images, replaced by neutral stand-ins (a warning each)");
  g->add_flag("--no-exr", o->no_exr, "Write PNG only");
  g->add_flag("-q,--quiet", o->quiet, "No progress lines");
}

}  // namespace

CLI::App* add_study_command(CLI::App& app, StudyCommandOptions* o) {
  CLI::App* study = app.add_subcommand("study", "Reproduce a paper's figures on the built-in scenes (images, JSON, HTML)");
  study->require_subcommand(1);
  CLI::App* pclt = study->add_subcommand("pclt", "Pixel cache light tracing paper: figs. 1, 5, 6, 7, 8 (fig. 9 explained)");
  add_common_options(pclt, &o->pclt, "Seconds per equal-time image (fig. 1); sets the iterations of figs. 5-8");
  pclt->callback([o] { o->study = "pclt"; });
  CLI::App* psf = study->add_subcommand(
      "psf", "Path space filtering papers (2014 consistent, 2021 hashed): their figures and equal-time comparisons");
  add_common_options(psf, &o->psf, "Sets the references' time (20 x this unless --reference-time); the equal-time budgets follow --equal-time-spp");
  psf->add_option("--equal-time-spp", o->psf_only.equal_time_spp,
                  "Paths per pixel of the hashed filter whose time is each equal-time figure's budget, comma-separated")
      ->delimiter(',')
      ->check(checked_integer("equal-time-spp", 1, 1 << 16))
      ->capture_default_str();
  psf->add_option("--figures", o->psf_only.figures,
                  "Make only these figures, comma-separated page ids (2014-fig2, 2021-fig1, ...; equal-time: every "
                  "equal-time figure); default all")
      ->delimiter(',');
  psf->add_option("--max-spp", o->psf_only.max_spp, "Last sample count of the progressive series (2014 fig. 3): 1, 4, 16, ...")
      ->check(checked_integer("max-spp", 1, 1 << 20))
      ->capture_default_str();
  psf->add_option("--vertex-set-resolution", o->psf_only.vertex_set_resolution,
                  "Image size WxH of the vertex sets of the hash table figures (2019 figs. 7, 8)")
      ->capture_default_str();
  psf->add_option("--temporal-frames", o->psf_only.temporal_frames,
                  "Frames of the orbit measurements of the hashed filter across frames (2021 sec. 3.4.1; fig. 9 uses up to 32); 0: skip")
      ->check(checked_integer("temporal-frames", 0, 100000))
      ->capture_default_str();
  psf->add_option("--eviction-frames", o->psf_only.eviction_frames,
                  "Frames of the eviction flight through textured-room, per eviction policy (2021 sec. 3.4.3); 0: skip")
      ->check(checked_integer("eviction-frames", 0, 10000000))
      ->capture_default_str();
  psf->add_option("--room-scene", o->psf_only.room_scene,
                  "The textured-room scene file of the temporal figures (relative: to the working folder, else to the repository of the binary)")
      ->capture_default_str();
  psf->callback([o] { o->study = "psf"; });
  CLI::App* gallery = study->add_subcommand(
      "gallery", "Render every scene of a folder that has a reference image beside it and compare (mean ratio, relMSE, error maps)");
  add_gallery_options(gallery, &o->gallery);
  gallery->callback([o] { o->study = "gallery"; });
  return study;
}

int run_study_command(const StudyCommandOptions& o) {
#if PATHSPACE_HAVE_STUDIES
  if (o.study == "psf") return studies::run_psf_study(o.psf, o.psf_only);
  if (o.study == "gallery") return studies::run_gallery_study(o.gallery);
  return studies::run_pclt_study(o.pclt);
#else
  throw Error(fmt::format("this build has no studies, so no '{}' (scripts/render builds the renderer alone); "
                          "scripts/build builds everything, or configure with -DPATHSPACE_STUDIES=ON",
                          o.study));
#endif
}

}  // namespace pathspace::cli
