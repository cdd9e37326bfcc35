// Binder, Fricke, Keller 2021 (hashed path space filtering, `--filter hashed`) in
// `pathspace study psf`: figs. 1, 4 and 10 rendered per scene, and the 2019 short version's figs. 7
// and 8 measured once on fixed vertex sets (studies/psf2021/hash_table_figures.h), one function each.
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "studies/psf2021/hash_table_figures.h"
#include "studies/psf/psf_figures.h"

namespace pathspace::studies {

namespace {

using study::Budget;
using study::Measurement;

double number(const study::Record& r, const char* field) { return r.number(field); }

const std::string& text(const study::Record& r, const char* field) {
  static const std::string none;
  const study::Value* v = r.find(field);
  const std::string* s = v ? std::get_if<std::string>(v) : nullptr;
  return s ? *s : none;
}

// One series per value of `group` (and vertex set), y against x, from a table's rows.
std::vector<study::PlotSeries> series_by(const study::Table& t, const std::string& vertex_set, const char* group,
                                         const std::string& name_format, const char* x, const char* y,
                                         const char* filter_field = nullptr, double filter_value = 0.0) {
  std::map<double, study::PlotSeries> by_group;
  for (const study::Record& r : t.rows) {
    if (text(r, "vertex_set") != vertex_set) continue;
    if (filter_field && number(r, filter_field) != filter_value) continue;
    study::PlotSeries& s = by_group[number(r, group)];
    s.name = fmt::format(fmt::runtime(name_format), number(r, group));
    s.points.push_back({number(r, x), number(r, y)});
  }
  std::vector<study::PlotSeries> out;
  for (auto& [key, s] : by_group) out.push_back(std::move(s));
  return out;
}

}  // namespace

// Fig. 1: one path per pixel, unfiltered and filtered.
void run_2021_fig1(const study::FigureRunner& fr, const PsfStudyParams&, std::vector<study::Figure>* figures) {
  study::Figure& f = study::find_figure(figures, "2021-fig1");
  const std::vector<Measurement> one = fr.run(f.id, {pt_with("PT 1 spp", "none"), pt_with("PT + hashed 1 spp", "hashed")},
                                              Budget::for_passes(1));
  const Measurement many = fr.run_one(f.id, pt_with("PT 64 spp", "none"), Budget::for_passes(64));
  f.runs.insert(f.runs.end(), one.begin(), one.end());
  f.runs.push_back(many);
  f.findings[fr.scene().id()] = fmt::format(
      "At 1 path per pixel the hashed filter's relMSE is {:.4g} against PT's {:.4g} ({:.1f}x lower); PT needs 64 paths per "
      "pixel for {:.4g}. The filter took {:.2f} ms for the pass (accumulate + lookup; paper: about 1.5 ms in HD on a GPU).",
      one[1].error.rel_mse, one[0].error.rel_mse, one[1].error.rel_mse > 0 ? one[0].error.rel_mse / one[1].error.rel_mse : 0.0,
      many.error.rel_mse, 1e3 * (one[1].metrics.number("accumulate_s_per_pass") + one[1].metrics.number("lookup_s_per_pass")));
}

// Fig. 4: voxel size sweep at equal paths per pixel.
void run_2021_fig4(const study::FigureRunner& fr, const PsfStudyParams&, std::vector<study::Figure>* figures) {
  study::Figure& f = study::find_figure(figures, "2021-fig4");
  const std::vector<double> scales = {3, 6, 12, 24, 48};
  std::vector<study::Configuration> configs;
  for (double s : scales) configs.push_back(pt_with(fmt::format("hashed s = {:g}", s), "hashed", {{"psf-scale", fmt::format("{:g}", s)}}));
  configs.push_back(pt_with("PT", "none"));
  const std::vector<Measurement> runs = fr.run(f.id, std::move(configs), Budget::for_passes(4));
  f.runs.insert(f.runs.end(), runs.begin(), runs.end());
  const std::vector<Measurement> hashed(runs.begin(), runs.end() - 1);
  const Measurement& pt = runs.back();
  size_t best = 0;
  for (size_t i = 1; i < hashed.size(); ++i)
    if (hashed[i].error.rel_mse < hashed[best].error.rel_mse) best = i;
  study::LinePlot plot;
  plot.title = fmt::format("{}: relMSE against voxel size, 4 spp", fr.scene().id());
  plot.x_label = "voxel edge s (projected pixels)";
  plot.y_label = "relMSE";
  plot.x_scale = plot.y_scale = study::AxisScale::log;
  size_t i = 0;
  plot.series = {rel_mse_series("PT + hashed", hashed, [&](const Measurement&) { return scales[i++]; }),
                 {"PT (no filter)", {{scales.front(), pt.error.rel_mse}, {scales.back(), pt.error.rel_mse}}}};
  f.plots.push_back(study::svg_line_plot(plot));
  f.findings[fr.scene().id()] = fmt::format(
      "Lowest relMSE at s = {:g} ({:.4g}); s = {:g}: {:.4g}, s = {:g}: {:.4g}; PT {:.4g} (paper: small voxels leave noise, large "
      "ones blur and leak).",
      scales[best], hashed[best].error.rel_mse, scales.front(), hashed.front().error.rel_mse, scales.back(),
      hashed.back().error.rel_mse, pt.error.rel_mse);
}

// Fig. 10: filtering at the second diffuse vertex.
void run_2021_fig10(const study::FigureRunner& fr, const PsfStudyParams&, std::vector<study::Figure>* figures) {
  study::Figure& f = study::find_figure(figures, "2021-fig10");
  const std::vector<Measurement> runs =
      fr.run(f.id,
             {pt_with("PT", "none"), pt_with("hashed, first vertex", "hashed"),
              pt_with("hashed, second vertex", "hashed", {{"psf-select", "nth"}, {"psf-nth", "2"}})},
             Budget::for_passes(16));
  f.runs.insert(f.runs.end(), runs.begin(), runs.end());
  f.findings[fr.scene().id()] = fmt::format(
      "relMSE at 16 paths per pixel: PT {:.4g}, first vertex {:.4g}, second vertex {:.4g} (paper: filtering at the second "
      "bounce reduces the variance of indirect light and keeps direct light sharp).",
      runs[0].error.rel_mse, runs[1].error.rel_mse, runs[2].error.rel_mse);
}

// 2019 figs. 7 and 8: the hash table on fixed vertex sets, plotted from the same tables the CSV study writes.
void run_hash_table_figures(int width, int height, int threads, bool quiet, std::vector<study::Figure>* figures) {
  study::Figure& f7 = study::find_figure(figures, "2019-fig7");
  study::Figure& f8 = study::find_figure(figures, "2019-fig8");
  study::HashTableSweep sweep;
  sweep.fig8_threads = threads;
  if (!quiet) sweep.progress = [](const std::string& line) { fmt::print("study: {}\n", line); };
  study::Table t7 = study::hash_collision_table(), t8 = study::filter_time_table();
  for (const auto kind : {study::VertexSetKind::primary, study::VertexSetKind::second_bounce}) {
    const auto set = study::make_vertex_set(kind, width, height);
    study::measure_hash_collisions(*set, study::vertex_set_name(kind), sweep, &t7);
    study::measure_filter_time(*set, study::vertex_set_name(kind), sweep, &t8);
  }
  for (const char* set : {"primary", "second_bounce"}) {
    const std::string hits = std::string(set) == "primary" ? "primary hits" : "second-bounce hits";
    study::LinePlot probes;
    probes.title = fmt::format("{}, {}x{}: extra probes per insertion", hits, width, height);
    probes.x_label = "hash table cells per pixel";
    probes.y_label = "extra probes per insertion";
    probes.x_scale = probes.y_scale = study::AxisScale::log;
    probes.series = series_by(t7, set, "psf_scale", "s = {:g} px", "cells_per_pixel", "extra_probes");
    f7.plots.push_back(study::svg_line_plot(probes));
    study::LinePlot occupancy = probes;
    occupancy.title = fmt::format("{}, {}x{}: occupancy", hits, width, height);
    occupancy.y_label = "occupied cells / cells";
    occupancy.series = series_by(t7, set, "psf_scale", "s = {:g} px", "cells_per_pixel", "occupancy");
    f7.plots.push_back(study::svg_line_plot(occupancy));
  }
  study::LinePlot time;
  time.title = fmt::format("filter time per pass, {}x{}", width, height);
  time.x_label = "voxel edge s (projected pixels)";
  time.y_label = "milliseconds";
  time.x_scale = time.y_scale = study::AxisScale::log;
  for (const char* set : {"primary", "second_bounce"})
    for (int combining : {1, 0}) {
      std::vector<study::PlotSeries> s = series_by(t8, set, "local_combining", "", "psf_scale", "total_ms", "local_combining", combining);
      for (study::PlotSeries& one : s) {
        one.name = fmt::format("{}{}", std::string(set) == "primary" ? "primary" : "2nd bounce", combining ? "" : ", no combining");
        time.series.push_back(std::move(one));
      }
    }
  f8.plots.push_back(study::svg_line_plot(time));
  double at_one_cell = 0.0;
  for (const study::Record& r : t7.rows)
    if (text(r, "vertex_set") == "second_bounce" && number(r, "psf_scale") == 4.0 && number(r, "cells_per_pixel") == 1.0)
      at_one_cell = number(r, "extra_probes");
  f7.findings[""] = fmt::format(
      "Second-bounce hits, s = 4 px, one cell per pixel: {:.4f} extra probes per insertion. Extra probes fall with the table "
      "size and the voxel size (data: study.json).",
      at_one_cell);
  double fine = 0.0, coarse = 0.0;
  for (const study::Record& r : t8.rows)
    if (text(r, "vertex_set") == "second_bounce" && number(r, "local_combining") == 1.0) {
      if (number(r, "psf_scale") == 0.5) fine = number(r, "total_ms");
      if (number(r, "psf_scale") == 32.0) coarse = number(r, "total_ms");
    }
  f8.findings[""] = fmt::format("Second-bounce hits with combining: {:.2f} ms per pass at s = 0.5 px, {:.2f} ms at s = 32 px ({} threads).",
                                fine, coarse, threads > 0 ? std::to_string(threads) : std::string("all"));
  f7.data["psf_fig7"] = std::move(t7);
  f8.data["psf_fig8"] = std::move(t8);
}

}  // namespace pathspace::studies
