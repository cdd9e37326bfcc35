#include "pathspace/study/figure.h"

#include "pathspace/base/error.h"

namespace pathspace::study {

Figure& find_figure(std::vector<Figure>* figures, const std::string& id) {
  for (Figure& f : *figures)
    if (f.id == id) return f;
  throw Error("study: no figure " + id);
}

nlohmann::ordered_json to_json(const Figure& f) {
  nlohmann::ordered_json j;
  j["id"] = f.id;
  j["title"] = f.title;
  j["paper"] = f.paper;
  j["reproduced"] = f.reproduced;
  if (f.reproduced) j["method"] = f.method;
  if (!f.reproduced) j["reason"] = f.not_reproduced_reason;
  j["findings"] = nlohmann::ordered_json::object();
  for (const auto& [scene, sentence] : f.findings) j["findings"][scene] = sentence;
  j["runs"] = nlohmann::ordered_json::array();
  for (const Measurement& m : f.runs) {
    nlohmann::ordered_json run = {{"figure", f.id}};
    const nlohmann::ordered_json fields = to_json(m);
    for (const auto& [key, value] : fields.items())
      if (key != "seed") run[key] = value;
    j["runs"].push_back(std::move(run));
  }
  if (!f.data.empty()) {
    j["data"] = nlohmann::ordered_json::object();
    for (const auto& [name, table] : f.data) j["data"][name] = to_json(table);
  }
  return j;
}

ReportSection report_section(const Figure& f) {
  ReportSection s;
  s.id = f.id;
  s.title = f.title;
  s.lead = "Paper: " + f.paper;
  if (f.reproduced)
    s.method = "Here: " + f.method;
  else
    s.note = f.not_reproduced_reason;
  s.metric_rows = f.metric_rows;
  s.measurements = f.runs;
  s.findings = f.findings;
  s.plots = f.plots;
  s.tables = f.shown_tables;
  return s;
}

std::vector<Measurement> FigureRunner::run(const std::string& figure, std::vector<Configuration> configurations, const Budget& budget,
                                           std::vector<ImageMetric> metrics) const {
  Experiment e;
  e.name = figure;
  e.configurations = std::move(configurations);
  e.seeds = {seed_};
  e.budget = budget;
  e.metrics = std::move(metrics);
  return runner_.run_scene(scene_, e);
}

Measurement FigureRunner::run_one(const std::string& figure, Configuration configuration, const Budget& budget,
                                  std::vector<ImageMetric> metrics) const {
  return run(figure, {std::move(configuration)}, budget, std::move(metrics)).front();
}

}  // namespace pathspace::study
