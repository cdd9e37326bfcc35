// The PCLT paper's figures as `pathspace study pclt` reproduces them on our built-in scenes: fig. 1
// (equal time PT/LT/BPT/SPPM/PCLT), fig. 5 (equal iterations SPPM vs PCLT), fig. 6 (visibility
// shortcuts), fig. 7 (light paths per iteration vs time and memory), fig. 8 (chained vs stochastic
// hash map); fig. 9 (many lights) is described and marked not reproduced.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "study_runner.h"

namespace pathspace::cli {

// An extra table row: a key of StudyRun::metrics and how to print it.
struct MetricRow {
  std::string key, label;
  enum class Format { number, seconds, bytes, percent } format = Format::number;
};

struct StudyFigure {
  std::string id;      // "fig1"
  std::string title;   // "Fig. 1 - equal time"
  std::string paper;   // what the paper compares and finds
  std::string method;  // how the study reproduces it here
  bool reproduced = true;
  std::string not_reproduced_reason;
  std::vector<MetricRow> metric_rows;
  std::vector<StudyRun> runs;  // every scene, in order
  nlohmann::ordered_json findings = nlohmann::ordered_json::object();  // scene id -> sentence from the numbers
};

struct PcltStudyParams {
  double time_s = 5.0;  // equal-time budget (fig. 1); the iteration count of figs. 5-8 follows from it
};

// The figures with their texts and no runs yet (fig. 9 included, not reproduced).
std::vector<StudyFigure> make_pclt_figures();
// Renders figs. 1 and 5-8 on one scene and appends the runs and findings to `figures`.
void run_pclt_figures(const StudyRunner& runner, const StudyScene& scene, const PcltStudyParams& params,
                      std::vector<StudyFigure>* figures);
// Sets fig. 9's reason from the largest light count of the built-in scenes.
void describe_fig9(size_t max_builtin_lights, std::vector<StudyFigure>* figures);

nlohmann::ordered_json to_json(const StudyFigure& figure);

}  // namespace pathspace::cli
