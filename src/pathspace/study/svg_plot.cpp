// SVG line plots (svg_plot.h). Coordinates are in SVG user units with y down; the plot area sits
// left of the legend, with room for tick labels and axis titles.
#include "pathspace/study/svg_plot.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "pathspace/study/markup_escape.h"

namespace pathspace::study {

namespace {

// Distinguishable in colour and in greyscale (with the marker shapes below).
constexpr const char* kColours[] = {"#1f5fbf", "#d0451b", "#2e9d3a", "#8a3fb0", "#c49a00", "#1c9fa8", "#555555", "#e377c2"};
constexpr int kColourCount = int(sizeof(kColours) / sizeof(kColours[0]));
constexpr int kMarginLeft = 64, kMarginRight = 12, kMarginTop = 28, kMarginBottom = 44, kLegendWidth = 170;

std::string tick_label(double v) {
  if (v == 0.0) return "0";
  const double a = std::abs(v);
  if (a >= 1e-3 && a < 1e5) return fmt::format("{:g}", v);
  return fmt::format("{:.0e}", v);
}

bool drawable(const PlotPoint& p, AxisScale xs, AxisScale ys) {
  if (!std::isfinite(p.x) || !std::isfinite(p.y)) return false;
  if (xs == AxisScale::log && p.x <= 0) return false;
  if (ys == AxisScale::log && p.y <= 0) return false;
  return true;
}

AxisLayout log_layout(double lo, double hi) {
  const int first = int(std::floor(std::log10(lo) + 1e-9));
  int last = int(std::ceil(std::log10(hi) - 1e-9));
  if (last <= first) last = first + 1;
  AxisLayout a;
  a.lo = std::pow(10.0, first);
  a.hi = std::pow(10.0, last);
  const bool fine = last - first <= 2;
  for (int e = first; e <= last; ++e) {
    const double d = std::pow(10.0, e);
    a.ticks.push_back({d, tick_label(d)});
    if (fine && e < last)
      for (double m : {2.0, 5.0}) a.ticks.push_back({m * d, tick_label(m * d)});
  }
  return a;
}

AxisLayout linear_layout(double lo, double hi) {
  if (hi <= lo) {
    const double pad = lo == 0.0 ? 1.0 : std::abs(lo) * 0.5;
    lo -= pad;
    hi += pad;
  }
  const double raw = (hi - lo) / 5.0;
  const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
  double step = magnitude;
  for (double m : {1.0, 2.0, 5.0, 10.0})
    if (m * magnitude >= raw) {
      step = m * magnitude;
      break;
    }
  AxisLayout a;
  a.lo = std::floor(lo / step + 1e-9) * step;
  a.hi = std::ceil(hi / step - 1e-9) * step;
  const int n = int(std::lround((a.hi - a.lo) / step));
  for (int i = 0; i <= n; ++i) {
    double v = a.lo + i * step;
    if (std::abs(v) < step * 1e-9) v = 0.0;  // no "-1e-17" at zero
    a.ticks.push_back({v, tick_label(v)});
  }
  return a;
}

// Maps data values to plot-area coordinates along one axis.
struct AxisMap {
  AxisLayout layout;
  AxisScale scale;
  double from, to;  // pixel coordinates of layout.lo and layout.hi
  double operator()(double v) const {
    const double t = scale == AxisScale::log ? (std::log10(v) - std::log10(layout.lo)) / (std::log10(layout.hi) - std::log10(layout.lo))
                                             : (v - layout.lo) / (layout.hi - layout.lo);
    return from + t * (to - from);
  }
};

std::string marker(int index, double x, double y, const char* colour) {
  switch (index % 3) {
    case 0: return fmt::format("<circle cx=\"{:.1f}\" cy=\"{:.1f}\" r=\"3\" fill=\"{}\"/>", x, y, colour);
    case 1: return fmt::format("<rect x=\"{:.1f}\" y=\"{:.1f}\" width=\"6\" height=\"6\" fill=\"{}\"/>", x - 3, y - 3, colour);
    default:
      return fmt::format("<path d=\"M{:.1f} {:.1f}L{:.1f} {:.1f}L{:.1f} {:.1f}Z\" fill=\"{}\"/>", x, y - 4, x + 4, y + 3, x - 4,
                         y + 3, colour);
  }
}

}  // namespace

AxisLayout axis_layout(double lo, double hi, AxisScale scale) {
  if (lo > hi) std::swap(lo, hi);
  return scale == AxisScale::log ? log_layout(lo, hi) : linear_layout(lo, hi);
}

std::string svg_line_plot(const LinePlot& plot) {
  const int w = plot.width, h = plot.height;
  std::string svg = fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" class=\"plot\" width=\"{0}\" height=\"{1}\" viewBox=\"0 0 {0} {1}\" role=\"img\" "
      "aria-label=\"{2}\" font-family=\"sans-serif\" font-size=\"11\">\n<rect width=\"{0}\" height=\"{1}\" fill=\"#fff\"/>\n"
      "<text x=\"{3}\" y=\"16\" text-anchor=\"middle\" font-size=\"13\">{2}</text>\n",
      w, h, escape_markup(plot.title), (w - kLegendWidth) / 2 + kMarginLeft / 2);

  double x_lo = std::numeric_limits<double>::infinity(), x_hi = -x_lo, y_lo = x_lo, y_hi = -x_lo;
  for (const PlotSeries& s : plot.series)
    for (const PlotPoint& p : s.points)
      if (drawable(p, plot.x_scale, plot.y_scale)) {
        x_lo = std::min(x_lo, p.x), x_hi = std::max(x_hi, p.x);
        y_lo = std::min(y_lo, p.y), y_hi = std::max(y_hi, p.y);
      }
  if (!(x_lo <= x_hi)) {
    svg += fmt::format("<text x=\"{}\" y=\"{}\" text-anchor=\"middle\">no data to plot</text>\n</svg>\n", w / 2, h / 2);
    return svg;
  }

  const double left = kMarginLeft, right = w - kLegendWidth - kMarginRight, top = kMarginTop, bottom = h - kMarginBottom;
  const AxisMap xm{axis_layout(x_lo, x_hi, plot.x_scale), plot.x_scale, left, right};
  const AxisMap ym{axis_layout(y_lo, y_hi, plot.y_scale), plot.y_scale, bottom, top};

  // Grid lines and tick labels.
  svg += "<g stroke=\"#e2e2e2\" stroke-width=\"1\">\n";
  for (const AxisTick& t : xm.layout.ticks) svg += fmt::format("<line x1=\"{0:.1f}\" y1=\"{1}\" x2=\"{0:.1f}\" y2=\"{2}\"/>\n", xm(t.value), top, bottom);
  for (const AxisTick& t : ym.layout.ticks) svg += fmt::format("<line x1=\"{1}\" y1=\"{0:.1f}\" x2=\"{2}\" y2=\"{0:.1f}\"/>\n", ym(t.value), left, right);
  svg += "</g>\n<g fill=\"#333\">\n";
  for (const AxisTick& t : xm.layout.ticks)
    svg += fmt::format("<text class=\"xtick\" x=\"{:.1f}\" y=\"{}\" text-anchor=\"middle\">{}</text>\n", xm(t.value), bottom + 15,
                       escape_markup(t.label));
  for (const AxisTick& t : ym.layout.ticks)
    svg += fmt::format("<text class=\"ytick\" x=\"{}\" y=\"{:.1f}\" text-anchor=\"end\">{}</text>\n", left - 5, ym(t.value) + 4,
                       escape_markup(t.label));
  svg += "</g>\n";
  svg += fmt::format("<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"none\" stroke=\"#444\"/>\n", left, top, right - left,
                     bottom - top);
  svg += fmt::format("<text x=\"{:.1f}\" y=\"{}\" text-anchor=\"middle\">{}</text>\n", (left + right) / 2, h - 8,
                     escape_markup(plot.x_label));
  svg += fmt::format("<text transform=\"translate(14 {:.1f}) rotate(-90)\" text-anchor=\"middle\">{}</text>\n", (top + bottom) / 2,
                     escape_markup(plot.y_label));

  // Series and legend.
  for (size_t i = 0; i < plot.series.size(); ++i) {
    const PlotSeries& s = plot.series[i];
    const char* colour = kColours[i % kColourCount];
    std::string points, markers;
    for (const PlotPoint& p : s.points) {
      if (!drawable(p, plot.x_scale, plot.y_scale)) continue;
      points += fmt::format("{}{:.1f},{:.1f}", points.empty() ? "" : " ", xm(p.x), ym(p.y));
      markers += marker(int(i), xm(p.x), ym(p.y), colour);
    }
    svg += fmt::format("<g class=\"series\"><title>{}</title>", escape_markup(s.name));
    if (!points.empty()) svg += fmt::format("<polyline points=\"{}\" fill=\"none\" stroke=\"{}\" stroke-width=\"1.6\"/>", points, colour);
    svg += markers + "</g>\n";
    const double ly = top + 8 + 16.0 * double(i);
    svg += fmt::format("<line x1=\"{0:.1f}\" y1=\"{1:.1f}\" x2=\"{2:.1f}\" y2=\"{1:.1f}\" stroke=\"{3}\" stroke-width=\"1.6\"/>{4}"
                       "<text x=\"{5:.1f}\" y=\"{6:.1f}\">{7}</text>\n",
                       right + 10, ly, right + 34, colour, marker(int(i), right + 22, ly, colour), right + 40, ly + 4,
                       escape_markup(s.name));
  }
  svg += "</svg>\n";
  return svg;
}

}  // namespace pathspace::study
