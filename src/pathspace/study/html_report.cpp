// Plain HTML and inline CSS, images as data URIs, no script (html_report.h).
#include "pathspace/study/html_report.h"

#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "pathspace/base/base64.h"
#include "pathspace/base/error.h"
#include "pathspace/study/error_colormap.h"
#include "pathspace/study/markup_escape.h"

namespace pathspace::study {

namespace {

constexpr int kThumbWidth = 160;  // CSS pixels; small renders are scaled up without smoothing

std::string escape(const std::string& text) { return escape_markup(text); }

// Each PNG becomes one CSS class holding its data URI; <div>s of that class show it. An image used
// by several sections (a reused run, the reference) is therefore embedded once.
class ImageSheet {
 public:
  explicit ImageSheet(std::string dir) : dir_(std::move(dir)) {}

  std::string tag(const std::string& path, const std::string& caption, int width, int height) {
    if (path.empty()) return "&ndash;";
    auto [it, added] = classes_.try_emplace(path, "i" + std::to_string(classes_.size()));
    if (added) {
      std::ifstream in(dir_ + "/" + path, std::ios::binary);
      if (!in) throw Error("study: cannot read '" + dir_ + "/" + path + "' for the HTML page");
      std::ostringstream bytes;
      bytes << in.rdbuf();
      css_ += fmt::format(".{}{{background-image:url(data:image/png;base64,{})}}\n", it->second, base64_encode(bytes.str()));
    }
    const int h = width > 0 ? kThumbWidth * height / width : kThumbWidth;
    return fmt::format("<div class=\"im {}\" style=\"height:{}px\" role=\"img\" title=\"{}\" aria-label=\"{}\"></div>",
                       it->second, h, escape(caption), escape(caption));
  }
  const std::string& css() const { return css_; }

 private:
  std::string dir_;
  std::map<std::string, std::string> classes_;
  std::string css_;
};

std::string format_metric(const Value* value, MetricFormat format) {
  if (!value) return "&ndash;";
  if (const std::string* s = std::get_if<std::string>(value)) return escape(*s);
  if (!is_number(*value)) return "&ndash;";
  const double v = as_number(*value);
  switch (format) {
    case MetricFormat::seconds: return fmt::format("{:.3f} s", v);
    case MetricFormat::bytes:
      return v >= 1024.0 * 1024.0 ? fmt::format("{:.2f} MiB", v / (1024.0 * 1024.0)) : fmt::format("{:.1f} KiB", v / 1024.0);
    case MetricFormat::percent: return fmt::format("{:+.2f}%", v);
    case MetricFormat::number: break;
  }
  return fmt::format("{:.4g}", v);
}

std::string settings_text(const nlohmann::ordered_json& settings) {
  if (!settings.is_object() || settings.empty()) return "defaults";
  std::string s;
  for (const auto& [key, value] : settings.items()) {
    if (!s.empty()) s += ", ";
    s += key + " " + (value.is_string() ? value.get<std::string>() : value.dump());
  }
  return escape(s);
}

constexpr const char* kStyle = R"(body{font-family:system-ui,sans-serif;margin:1.5em;color:#222;background:#fafafa;max-width:1400px}
h1{font-size:1.5em}h2{font-size:1.25em;margin-top:2em;border-bottom:1px solid #ccc}h3{font-size:1.05em;margin-bottom:.3em}
table{border-collapse:collapse;margin:.4em 0 .8em 0;font-size:.85em}caption{text-align:left;font-weight:600;padding:.2em 0}td,th{border:1px solid #ddd;padding:3px 6px;text-align:center;vertical-align:middle}
th{background:#eee}td.k{text-align:left;background:#f3f3f3;font-weight:600;white-space:nowrap}td.s{font-size:.8em;color:#555;max-width:170px}
.im{width:160px;background-size:100% 100%;image-rendering:pixelated;margin:auto}.best{font-weight:700;color:#0a6}
.paper,.method{max-width:70em}.paper{font-style:italic}.finding{background:#fff7d6;padding:.4em .6em;border-left:4px solid #e0b000;max-width:70em}
.plots{display:flex;flex-wrap:wrap;gap:12px;margin:.6em 0}.plots svg{border:1px solid #ddd;flex:none}
.legend{display:inline-block;width:320px;height:14px;border:1px solid #999;vertical-align:middle}.nr{background:#fde8e8;padding:.6em;border-left:4px solid #c33}
)";

void section_table(std::string& html, const ReportSection& section, const SceneSummary& scene, ImageSheet& sheet) {
  std::vector<const Measurement*> runs;
  for (const Measurement& m : section.measurements)
    if (m.scene_id == scene.id) runs.push_back(&m);
  if (runs.empty()) return;
  const Measurement* best = runs.front();
  for (const Measurement* r : runs)
    if (r->error.rel_mse < best->error.rel_mse) best = r;
  const nlohmann::ordered_json ref = to_json(scene.reference);
  const int w = scene.width, h = scene.height;
  html += fmt::format("<h3>{} ({})</h3>\n<table>\n<tr><th></th><th>reference</th>", escape(scene.name), escape(scene.id));
  for (const Measurement* r : runs) html += "<th>" + escape(r->label) + "</th>";
  html += "</tr>\n<tr><td class=k>image</td><td>" + sheet.tag(scene.reference_png, scene.id + " reference", w, h) + "</td>";
  for (const Measurement* r : runs) html += "<td>" + sheet.tag(r->image_png, scene.id + " " + r->label, w, h) + "</td>";
  html += "</tr>\n<tr><td class=k>relative squared error</td><td>&ndash;</td>";
  for (const Measurement* r : runs) html += "<td>" + sheet.tag(r->error_png, scene.id + " " + r->label + " error", w, h) + "</td>";
  html += "</tr>\n";
  auto row = [&](const std::string& key, const std::string& ref_value, auto&& value) {
    html += fmt::format("<tr><td class=k>{}</td><td>{}</td>", escape(key), ref_value);
    for (const Measurement* r : runs) html += "<td>" + value(*r) + "</td>";
    html += "</tr>\n";
  };
  row("integrator", escape(ref.value("integrator", "")), [](const Measurement& r) {
    return escape(r.integrator) + (r.filter.empty() || r.filter == "none" ? "" : " + " + escape(r.filter));
  });
  row("time", ref.contains("time_s") ? fmt::format("{:.2f} s", ref.value("time_s", 0.0)) : std::string("&ndash;"),
      [](const Measurement& r) {
        return r.time_budget_s > 0 ? fmt::format("{:.2f} s (budget {:.3g} s)", r.time_s, r.time_budget_s)
                                   : fmt::format("{:.2f} s", r.time_s);
      });
  row("iterations", ref.contains("iterations") ? std::to_string(ref.value("iterations", 0u)) : std::string("&ndash;"),
      [](const Measurement& r) { return std::to_string(r.iterations); });
  row("relMSE", ref.contains("noise_rel_mse") ? fmt::format("noise {:.3g}", ref.value("noise_rel_mse", 0.0)) : std::string("&ndash;"),
      [&](const Measurement& r) {
        const std::string v = fmt::format("{:.4g}", r.error.rel_mse);
        return &r == best && runs.size() > 1 ? "<span class=best>" + v + "</span>" : v;
      });
  row("MSE", "&ndash;", [](const Measurement& r) { return fmt::format("{:.4g}", r.error.mse); });
  row("energy vs reference", "&ndash;", [](const Measurement& r) {
    return r.error.mean_reference > 0 ? fmt::format("{:+.2f}%", 100.0 * (r.error.mean_image / r.error.mean_reference - 1.0))
                                      : std::string("&ndash;");
  });
  for (const MetricRow& m : section.metric_rows)
    row(m.label, "&ndash;", [&](const Measurement& r) { return format_metric(r.metrics.find(m.key), m.format); });
  const std::string ref_settings = ref.contains("seed") ? "seed " + escape(ref["seed"].dump()) : "&ndash;";
  html += "<tr><td class=k>settings</td><td class=s>" + ref_settings + "</td>";
  for (const Measurement* r : runs)
    html += "<td class=s>" + settings_text(to_json(r->settings)) +
            (r->same_render_as.empty() ? "" : "<br>(same render as " + escape(r->same_render_as) + ")") + "</td>";
  html += "</tr>\n</table>\n";
  if (const auto it = section.findings.find(scene.id); it != section.findings.end())
    html += "<p class=finding>" + escape(it->second) + "</p>\n";
}

void data_table(std::string& html, const std::string& title, const Table& table) {
  const std::vector<Column> columns = table.effective_columns();
  html += "<table>\n";
  if (!title.empty()) html += "<caption>" + escape(title) + "</caption>\n";
  html += "<tr>";
  for (const Column& c : columns) html += "<th>" + escape(c.name) + "</th>";
  html += "</tr>\n";
  for (const Record& r : table.rows) {
    html += "<tr>";
    for (const Column& c : columns) {
      const Value* v = r.find(c.source());
      html += "<td>" + (v ? escape(cell_text(*v, c.format)) : std::string("&ndash;")) + "</td>";
    }
    html += "</tr>\n";
  }
  html += "</table>\n";
}

std::string scene_text(const SceneSummary& s) {
  const nlohmann::ordered_json ref = to_json(s.reference);
  const std::string reference = ref.contains("image_file")
                                    ? "reference " + escape(ref.value("image_file", ""))
                                    : fmt::format("reference {} for {:.1f} s", escape(ref.value("integrator", "")), ref.value("time_s", 0.0));
  return fmt::format("{} ({}, {} light{}, {})", escape(s.name), escape(s.id), s.light_count, s.light_count == 1 ? "" : "s", reference);
}

}  // namespace

std::string html_report(const std::string& out_dir, const ReportPage& page) {
  ImageSheet sheet(out_dir);
  std::string body = "<h1>" + escape(page.title) + "</h1>\n<p>Study settings: ";
  body += settings_text(page.settings) + ".</p>\n";
  body += "<p>relMSE = mean over pixels and channels of (I &minus; R)&sup2; / (R&sup2; + 0.01) against the reference; the "
          "reference column's value is the reference's own estimated relMSE (its noise floor). Lowest relMSE per table in "
          "<span class=best>green</span>. Error maps show the per-pixel relative squared error on a log scale: ";
  body += fmt::format("{:g} <span class=legend style=\"background:{}\"></span> {:g} and above.</p>\n", kErrorMapLow,
                      error_ramp_css_gradient(), kErrorMapHigh);
  body += "<p>Scenes: ";
  for (size_t i = 0; i < page.scenes.size(); ++i) body += (i ? "; " : "") + scene_text(page.scenes[i]);
  body += ".</p>\n";
  for (const ReportSection& s : page.sections) {
    body += fmt::format("<h2 id=\"{}\">{}</h2>\n", escape(s.id), escape(s.title));
    if (!s.lead.empty()) body += "<p class=paper>" + escape(s.lead) + "</p>\n";
    if (!s.note.empty()) {
      body += "<p class=nr>" + escape(s.note) + "</p>\n";
      continue;
    }
    if (!s.method.empty()) body += "<p class=method>" + escape(s.method) + "</p>\n";
    if (!s.plots.empty()) {
      body += "<div class=plots>\n";
      for (const std::string& svg : s.plots) body += svg;
      body += "</div>\n";
    }
    for (const auto& [title, table] : s.tables) data_table(body, title, table);
    if (const auto it = s.findings.find(""); it != s.findings.end()) body += "<p class=finding>" + escape(it->second) + "</p>\n";
    for (const SceneSummary& scene : page.scenes) section_table(body, s, scene, sheet);
  }
  return "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>" + escape(page.title) +
         "</title>\n<style>\n" + kStyle + sheet.css() + "</style>\n</head>\n<body>\n" + body + "</body>\n</html>\n";
}

}  // namespace pathspace::study
