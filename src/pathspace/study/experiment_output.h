// The outputs of an ExperimentResult: a CSV/JSON table with one row per measurement, a JSON
// document (scenes with their references, every run) and the HTML page (html_report.h).
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "pathspace/study/experiment_result.h"
#include "pathspace/study/html_report.h"
#include "pathspace/study/table.h"

namespace pathspace::study {

// One row per measurement (to_record), columns in order of first appearance.
Table results_table(const ExperimentResult& result);

// A scene's JSON: its reference record plus name and lights.
nlohmann::ordered_json to_json(const SceneSummary& scene);
// {"experiment": name, "scenes": {id: ...}, "runs": [to_json(measurement), ...]}.
nlohmann::ordered_json to_json(const ExperimentResult& result);

// One section with every measurement; metric rows for every metric, in order of first appearance
// (formats from the configurations' StatisticMetric where the experiment is given).
ReportPage report_page(const ExperimentResult& result, const Experiment* experiment = nullptr);

struct OutputFiles {
  std::string csv, json, html;
};
// Writes <out_dir>/<slug(name)>.csv, .json and .html (atomically); the HTML embeds the images the
// runner wrote into out_dir.
OutputFiles write_results(const ExperimentResult& result, const std::string& out_dir, const Experiment* experiment = nullptr);

}  // namespace pathspace::study
