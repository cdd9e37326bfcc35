// The PCLT paper's figures as `pathspace study pclt` reproduces them on our built-in scenes, defined
// on the experiment harness (src/pathspace/study/): fig. 1 (equal time PT/LT/BPT/SPPM/PCLT), fig. 5
// (equal iterations SPPM vs PCLT), fig. 6 (visibility shortcuts), fig. 7 (light paths per iteration
// vs time and memory), fig. 8 (chained vs stochastic hash map); fig. 9 (many lights) is described
// and marked not reproduced.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "pathspace/study/experiment_runner.h"
#include "pathspace/study/html_report.h"

namespace pathspace::cli {

struct StudyFigure {
  std::string id;      // "fig1"
  std::string title;   // "Fig. 1 - equal time"
  std::string paper;   // what the paper compares and finds
  std::string method;  // how the study reproduces it here
  bool reproduced = true;
  std::string not_reproduced_reason;
  std::vector<study::MetricRow> metric_rows;
  std::vector<study::Measurement> runs;         // every scene, in order
  std::map<std::string, std::string> findings;  // scene id -> sentence from the numbers
};

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

// study.json's figure object; each run is {"figure": id, ...to_json(measurement)}.
nlohmann::ordered_json to_json(const StudyFigure& figure);
// The figure as a section of the HTML page ("Paper: ...", "Here: ...").
study::ReportSection report_section(const StudyFigure& figure);

}  // namespace pathspace::cli
