// Figure: one paper figure as a study reproduces it (`pathspace study pclt`, `pathspace study psf`):
// the paper's claim, how the study reproduces it, its runs on every scene with a finding sentence
// per scene computed from the numbers, and optional plots (inline SVG, svg_plot.h) and data tables.
// It becomes an object of study.json and a section of study.html. FigureRunner renders a figure's
// configurations on one prepared scene with one seed.
#pragma once

#include <map>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "pathspace/study/experiment_runner.h"
#include "pathspace/study/html_report.h"
#include "pathspace/study/table.h"

namespace pathspace::study {

struct Figure {
  std::string id;      // "fig1", "2014-fig2"
  std::string title;   // "Fig. 1 - equal time"
  std::string paper;   // what the paper compares and finds
  std::string method;  // how the study reproduces it here
  bool reproduced = true;
  std::string not_reproduced_reason;
  std::vector<MetricRow> metric_rows;
  std::vector<Measurement> runs;         // every scene, in order
  std::map<std::string, std::string> findings;  // scene id -> sentence from the numbers
  std::vector<std::string> plots;        // SVG elements shown above the image tables
  std::map<std::string, Table> data;     // measurements without images (study.json "data": name -> table)
  // Tables also shown in study.html, after the plots (title, table); they are not in study.json
  // unless also in `data`.
  std::vector<std::pair<std::string, Table>> shown_tables;
};

// The figure with this id; throws pathspace::Error when there is none.
Figure& find_figure(std::vector<Figure>* figures, const std::string& id);

// study.json's figure object; each run is {"figure": id, ...to_json(measurement)} without the seed
// (every run has the study's seed, settings.seed).
nlohmann::ordered_json to_json(const Figure& figure);
// The figure as a section of the HTML page ("Paper: ...", "Here: ...").
ReportSection report_section(const Figure& figure);

// Runs the configurations of one figure on one scene (one seed), in order.
class FigureRunner {
 public:
  FigureRunner(const ExperimentRunner& runner, const PreparedScene& scene, uint64_t seed)
      : runner_(runner), scene_(scene), seed_(seed) {}

  std::vector<Measurement> run(const std::string& figure, std::vector<Configuration> configurations, const Budget& budget,
                               std::vector<ImageMetric> metrics = {}) const;
  Measurement run_one(const std::string& figure, Configuration configuration, const Budget& budget,
                      std::vector<ImageMetric> metrics = {}) const;

  const PreparedScene& scene() const { return scene_; }
  const ExperimentRunner& runner() const { return runner_; }

 private:
  const ExperimentRunner& runner_;
  const PreparedScene& scene_;
  uint64_t seed_;
};

}  // namespace pathspace::study
