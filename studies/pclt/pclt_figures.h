// The PCLT paper's figures as `pathspace study pclt` reproduces them on our built-in scenes, defined
// on the experiment harness (src/pathspace/study/): fig. 1 (equal time PT/LT/BPT/SPPM/PCLT), fig. 5
// (equal iterations SPPM vs PCLT), fig. 6 (visibility shortcuts), fig. 7 (light paths per iteration
// vs time and memory), fig. 8 (chained vs stochastic hash map); fig. 9 (many lights) is described
// and marked not reproduced.
#pragma once

#include <cstdint>
#include <vector>

#include "pathspace/study/figure.h"

namespace pathspace::studies {

// The figures of both studies are study::Figure (src/pathspace/study/figure.h).
using StudyFigure = study::Figure;

struct PcltStudyParams {
  double time_s = 5.0;  // equal-time budget (fig. 1); the iteration count of figs. 5-8 follows from it
  uint64_t seed = 0;    // of every run (the reference has its own)
};

// The figures with their texts and no runs yet (fig. 9 included, not reproduced).
std::vector<StudyFigure> make_pclt_figures();
// Renders figs. 1 and 5-8 on one scene and appends the runs and findings to `figures`. The runner
// must keep images (RunnerOptions::keep_images: fig. 6 compares with fig. 1's image); they are
// dropped from the runs before it returns.
void run_pclt_figures(const study::ExperimentRunner& runner, const study::PreparedScene& scene, const PcltStudyParams& params,
                      std::vector<StudyFigure>* figures);
// Sets fig. 9's reason from the largest light count of the built-in scenes.
void describe_fig9(size_t max_builtin_lights, std::vector<StudyFigure>* figures);

}  // namespace pathspace::studies
