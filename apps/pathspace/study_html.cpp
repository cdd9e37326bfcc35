// HTML page of `pathspace study` (study_html.h): the PCLT paper's figures as tables of thumbnails,
// error maps and numbers. Plain HTML and inline CSS, images as data URIs, no script.
#include "study_html.h"

#include <fstream>
#include <map>
#include <sstream>

#include <fmt/format.h>

#include "error_colormap.h"
#include "pathspace/base/base64.h"
#include "pathspace/base/error.h"

namespace pathspace::cli {

namespace {

constexpr int kThumbWidth = 160;  // CSS pixels; small renders are scaled up without smoothing

std::string escape(const std::string& text) {
  std::string s;
  for (char c : text) {
    switch (c) {
      case '&': s += "&amp;"; break;
      case '<': s += "&lt;"; break;
      case '>': s += "&gt;"; break;
      case '"': s += "&quot;"; break;
      default: s += c;
    }
  }
  return s;
}

// Each PNG becomes one CSS class holding its data URI; <div>s of that class show it. An image used
// by several figures (a reused run, the reference) is therefore embedded once.
class ImageSheet {
 public:
  explicit ImageSheet(std::string dir) : dir_(std::move(dir)) {}

  std::string tag(const std::string& path, const std::string& caption, int width, int height) {
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

std::string format_metric(const nlohmann::ordered_json& value, MetricRow::Format format) {
  if (!value.is_number()) return "&ndash;";
  const double v = value.get<double>();
  switch (format) {
    case MetricRow::Format::seconds: return fmt::format("{:.3f} s", v);
    case MetricRow::Format::bytes:
      return v >= 1024.0 * 1024.0 ? fmt::format("{:.2f} MiB", v / (1024.0 * 1024.0)) : fmt::format("{:.1f} KiB", v / 1024.0);
    case MetricRow::Format::percent: return fmt::format("{:+.2f}%", v);
    case MetricRow::Format::number: break;
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
table{border-collapse:collapse;margin:.4em 0 .8em 0;font-size:.85em}td,th{border:1px solid #ddd;padding:3px 6px;text-align:center;vertical-align:middle}
th{background:#eee}td.k{text-align:left;background:#f3f3f3;font-weight:600;white-space:nowrap}td.s{font-size:.8em;color:#555;max-width:170px}
.im{width:160px;background-size:100% 100%;image-rendering:pixelated;margin:auto}.best{font-weight:700;color:#0a6}
.paper,.method{max-width:70em}.paper{font-style:italic}.finding{background:#fff7d6;padding:.4em .6em;border-left:4px solid #e0b000;max-width:70em}
.legend{display:inline-block;width:320px;height:14px;border:1px solid #999;vertical-align:middle}.nr{background:#fde8e8;padding:.6em;border-left:4px solid #c33}
)";

struct Ctx {
  ImageSheet* sheet;
  const StudySceneSummary* scene;
  int width, height;
};

void figure_table(std::string& html, const StudyFigure& f, const Ctx& c) {
  std::vector<const StudyRun*> runs;
  for (const StudyRun& r : f.runs)
    if (r.scene_id == c.scene->id) runs.push_back(&r);
  if (runs.empty()) return;
  const StudyRun* best = runs.front();
  for (const StudyRun* r : runs)
    if (r->error.rel_mse < best->error.rel_mse) best = r;
  const nlohmann::ordered_json& ref = c.scene->reference;
  html += fmt::format("<h3>{} ({})</h3>\n<table>\n<tr><th></th><th>reference</th>", escape(c.scene->name), escape(c.scene->id));
  for (const StudyRun* r : runs) html += "<th>" + escape(r->label) + "</th>";
  html += "</tr>\n<tr><td class=k>image</td><td>" +
          c.sheet->tag(c.scene->reference_png, c.scene->id + " reference", c.width, c.height) + "</td>";
  for (const StudyRun* r : runs) html += "<td>" + c.sheet->tag(r->image_png, c.scene->id + " " + r->label, c.width, c.height) + "</td>";
  html += "</tr>\n<tr><td class=k>relative squared error</td><td>&ndash;</td>";
  for (const StudyRun* r : runs)
    html += "<td>" + c.sheet->tag(r->error_png, c.scene->id + " " + r->label + " error", c.width, c.height) + "</td>";
  html += "</tr>\n";
  auto row = [&](const char* key, const std::string& ref_value, auto&& value) {
    html += fmt::format("<tr><td class=k>{}</td><td>{}</td>", key, ref_value);
    for (const StudyRun* r : runs) html += "<td>" + value(*r) + "</td>";
    html += "</tr>\n";
  };
  row("integrator", escape(ref.value("integrator", "")), [](const StudyRun& r) { return escape(r.integrator); });
  row("time", fmt::format("{:.2f} s", ref.value("time_s", 0.0)), [](const StudyRun& r) {
    return r.time_budget_s > 0 ? fmt::format("{:.2f} s (budget {:.3g} s)", r.time_s, r.time_budget_s) : fmt::format("{:.2f} s", r.time_s);
  });
  row("iterations", std::to_string(ref.value("iterations", 0u)), [](const StudyRun& r) { return std::to_string(r.iterations); });
  row("relMSE", fmt::format("noise {:.3g}", ref.value("noise_rel_mse", 0.0)), [&](const StudyRun& r) {
    const std::string v = fmt::format("{:.4g}", r.error.rel_mse);
    return &r == best && runs.size() > 1 ? "<span class=best>" + v + "</span>" : v;
  });
  row("MSE", "&ndash;", [](const StudyRun& r) { return fmt::format("{:.4g}", r.error.mse); });
  row("energy vs reference", "&ndash;", [](const StudyRun& r) {
    return r.error.mean_reference > 0 ? fmt::format("{:+.2f}%", 100.0 * (r.error.mean_image / r.error.mean_reference - 1.0))
                                      : std::string("&ndash;");
  });
  for (const MetricRow& m : f.metric_rows)
    row(m.label.c_str(), "&ndash;", [&](const StudyRun& r) {
      return format_metric(r.metrics.contains(m.key) ? r.metrics[m.key] : nlohmann::ordered_json(), m.format);
    });
  html += "<tr><td class=k>settings</td><td class=s>seed " + escape(ref.value("seed", nlohmann::ordered_json(0)).dump()) + "</td>";
  for (const StudyRun* r : runs)
    html += "<td class=s>" + settings_text(r->settings) +
            (r->reused_from.empty() ? "" : "<br>(same render as " + escape(r->reused_from) + ")") + "</td>";
  html += "</tr>\n</table>\n";
  if (f.findings.contains(c.scene->id))
    html += "<p class=finding>" + escape(f.findings[c.scene->id].get<std::string>()) + "</p>\n";
}

}  // namespace

std::string study_html(const std::string& out_dir, const std::string& title, const nlohmann::ordered_json& settings,
                       const std::vector<StudySceneSummary>& scenes, const std::vector<StudyFigure>& figures) {
  ImageSheet sheet(out_dir);
  const int width = settings.value("width", 128), height = settings.value("height", 128);
  std::string body = "<h1>" + escape(title) + "</h1>\n<p>Study settings: ";
  body += settings_text(settings) + ".</p>\n";
  body += "<p>relMSE = mean over pixels and channels of (I &minus; R)&sup2; / (R&sup2; + 0.01) against the reference; the "
          "reference column's value is the reference's own estimated relMSE (its noise floor). Lowest relMSE per table in "
          "<span class=best>green</span>. Error maps show the per-pixel relative squared error on a log scale: ";
  body += fmt::format("{:g} <span class=legend style=\"background:{}\"></span> {:g} and above.</p>\n", kErrorMapLow,
                      error_ramp_css_gradient(), kErrorMapHigh);
  body += "<p>Scenes: ";
  for (size_t i = 0; i < scenes.size(); ++i)
    body += fmt::format("{}{} ({}, {} light{}, reference {} for {:.1f} s)", i ? "; " : "", escape(scenes[i].name),
                        escape(scenes[i].id), scenes[i].light_count, scenes[i].light_count == 1 ? "" : "s",
                        escape(scenes[i].reference.value("integrator", "")), scenes[i].reference.value("time_s", 0.0));
  body += ".</p>\n";
  for (const StudyFigure& f : figures) {
    body += fmt::format("<h2 id=\"{}\">{}</h2>\n<p class=paper>Paper: {}</p>\n", f.id, escape(f.title), escape(f.paper));
    if (!f.reproduced) {
      body += "<p class=nr>" + escape(f.not_reproduced_reason) + "</p>\n";
      continue;
    }
    body += "<p class=method>Here: " + escape(f.method) + "</p>\n";
    for (const StudySceneSummary& s : scenes) figure_table(body, f, Ctx{&sheet, &s, width, height});
  }
  return "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>" + escape(title) + "</title>\n<style>\n" +
         kStyle + sheet.css() + "</style>\n</head>\n<body>\n" + body + "</body>\n</html>\n";
}

}  // namespace pathspace::cli
