// `pathspace study pclt` (pclt_study.h): one scene at a time over the PCLT paper's figures.
#include "studies/pclt/pclt_study.h"

#include <algorithm>

#include "pathspace/scene/builtin_scenes.h"
#include "studies/common/study_setup.h"
#include "studies/pclt/pclt_figures.h"

namespace pathspace::studies {

namespace {

size_t max_builtin_light_count() {
  size_t n = 0;
  for (const BuiltinSceneInfo& info : builtin_scenes()) n = std::max(n, make_builtin_scene(info.name, 1, 1).lights.size());
  return n;
}

}  // namespace

int run_pclt_study(const StudyOptions& o) {
  const StudySetup setup = prepare_study(o);
  const study::ExperimentRunner runner = make_study_runner(o, /*keep_images=*/true);  // fig. 6 compares with fig. 1's image
  StudyDocument doc = study_document(o, setup, "pclt", "Pixel Cache Light Tracing",
                                     "Pixel cache light tracing: the paper's figures on pathspace scenes");
  doc.figures = make_pclt_figures();
  describe_fig9(max_builtin_light_count(), &doc.figures);
  for (const std::string& name : setup.scene_names) {
    // One scene at a time: its geometry, acceleration structure and images are freed before the next.
    const study::PreparedScene scene = runner.prepare(study::SceneSpec{name, setup.width, setup.height},
                                                         study_reference(o, setup, name));
    run_pclt_figures(runner, scene, PcltStudyParams{o.time_s, o.seed}, &doc.figures);
    doc.scenes.push_back(scene.summary);
  }
  write_study(o, doc);
  return 0;
}

}  // namespace pathspace::studies
