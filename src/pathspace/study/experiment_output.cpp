#include "pathspace/study/experiment_output.h"

#include "pathspace/base/error.h"
#include "pathspace/io/atomic_file.h"
#include "pathspace/study/image_files.h"

namespace pathspace::study {

Table results_table(const ExperimentResult& result) {
  Table t;
  for (const Measurement& m : result.measurements) t.rows.push_back(to_record(m));
  return t;
}

nlohmann::ordered_json to_json(const SceneSummary& scene) {
  nlohmann::ordered_json j = to_json(scene.reference);
  j["name"] = scene.name;
  j["lights"] = scene.light_count;
  j["width"] = scene.width;
  j["height"] = scene.height;
  return j;
}

nlohmann::ordered_json to_json(const ExperimentResult& result) {
  nlohmann::ordered_json j;
  j["experiment"] = result.name;
  j["scenes"] = nlohmann::ordered_json::object();
  for (const SceneSummary& s : result.scenes) j["scenes"][s.id] = to_json(s);
  j["runs"] = nlohmann::ordered_json::array();
  for (const Measurement& m : result.measurements) j["runs"].push_back(to_json(m));
  return j;
}

ReportPage report_page(const ExperimentResult& result, const Experiment* experiment) {
  ReportPage page;
  page.title = result.name;
  page.settings["experiment"] = result.name;
  if (experiment) {
    page.settings["seeds"] = experiment->seeds;
    if (experiment->budget.timed())
      page.settings["time_s"] = experiment->budget.seconds;
    else
      page.settings["passes"] = experiment->budget.passes;
  }
  page.scenes = result.scenes;
  ReportSection section;
  section.id = slug(result.name);
  section.title = result.name;
  section.measurements = result.measurements;
  for (const Measurement& m : result.measurements)
    for (const Field& f : m.metrics.fields()) {
      bool seen = false;
      for (const MetricRow& r : section.metric_rows) seen = seen || r.key == f.name;
      if (seen) continue;
      MetricRow row{f.name, f.name, MetricFormat::number};
      if (experiment)
        for (const Configuration& c : experiment->configurations)
          for (const StatisticMetric& s : c.statistics)
            if (s.name() == f.name) row.format = s.format;
      section.metric_rows.push_back(row);
    }
  page.sections.push_back(std::move(section));
  return page;
}

OutputFiles write_results(const ExperimentResult& result, const std::string& out_dir, const Experiment* experiment) {
  if (out_dir.empty()) throw Error("study: write_results needs an output folder");
  const std::string base = out_dir + "/" + (slug(result.name).empty() ? std::string("experiment") : slug(result.name));
  OutputFiles f{base + ".csv", base + ".json", base + ".html"};
  write_csv(f.csv, results_table(result));
  write_text_file(f.json, to_json(result).dump(2) + "\n");
  write_text_file(f.html, html_report(out_dir, report_page(result, experiment)));
  return f;
}

}  // namespace pathspace::study
