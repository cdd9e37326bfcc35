// The one-page HTML report of an experiment or study: per section (a paper figure, an experiment)
// a table per scene with the reference, the renders, their false-colour error maps and numbers side
// by side. Self-contained: inline CSS, every PNG embedded once as a base64 data URI (CSS classes, so
// an image shown in several sections is stored once); no script and no external resource, so the
// page can be mailed or committed as it is. Plots are inline SVG (svg_plot.h).
#pragma once

#include <map>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "pathspace/study/experiment.h"
#include "pathspace/study/measurement.h"
#include "pathspace/study/prepared_scene.h"
#include "pathspace/study/table.h"

namespace pathspace::study {

// An extra table row: a key of Measurement::metrics and how to print it.
struct MetricRow {
  std::string key, label;
  MetricFormat format = MetricFormat::number;
};

struct ReportSection {
  std::string id, title;
  std::string lead;    // an italic paragraph under the title (e.g. "Paper: ..."); empty: none
  std::string method;  // a plain paragraph (e.g. "Here: ..."); empty: none
  std::string note;    // when set, shown highlighted instead of the tables (e.g. why it is not reproduced)
  std::vector<MetricRow> metric_rows;
  std::vector<Measurement> measurements;      // every scene, in order
  std::map<std::string, std::string> findings;  // scene id -> a sentence from the numbers ("": about the whole section)
  std::vector<std::string> plots;  // inline <svg> elements (svg_plot.h), shown before the scene tables
  // Data tables shown as HTML tables after the plots (title, table; cells formatted by their
  // column's format, table.h).
  std::vector<std::pair<std::string, Table>> tables;
};

struct ReportPage {
  std::string title;
  nlohmann::ordered_json settings;  // printed as "key value, ..."
  std::vector<SceneSummary> scenes;
  std::vector<ReportSection> sections;
};

// Builds the page; images are read from out_dir (paths in the measurements are relative to it).
// Throws pathspace::Error when an image it names cannot be read.
std::string html_report(const std::string& out_dir, const ReportPage& page);

}  // namespace pathspace::study
