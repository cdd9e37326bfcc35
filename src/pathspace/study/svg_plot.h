// Line plots as inline SVG for the study pages (relMSE against samples per pixel, collisions against
// table size, filter time against voxel size): axes with ticks and labels, linear or logarithmic
// scales, one polyline with markers per series and a legend. Drawn by our own code so that a page
// needs no plotting library, no script and no network; the text is well-formed XML.
#pragma once

#include <string>
#include <vector>

namespace pathspace::study {

enum class AxisScale { linear, log };

struct PlotPoint {
  double x = 0.0, y = 0.0;
};

struct PlotSeries {
  std::string name;  // legend text
  std::vector<PlotPoint> points;  // drawn in the order given; non-finite points (and <= 0 on a log axis) are skipped
};

struct LinePlot {
  std::string title, x_label, y_label;
  AxisScale x_scale = AxisScale::linear, y_scale = AxisScale::linear;
  std::vector<PlotSeries> series;
  int width = 560, height = 320;  // the whole picture, legend included
};

struct AxisTick {
  double value = 0.0;
  std::string label;
};

// The axis range and its ticks for data in [lo, hi]. Log: the range widens to whole decades and the
// ticks are the powers of ten (plus 2 and 5 times them when the range spans at most two decades);
// lo and hi must be positive. Linear: "nice" steps of 1, 2 or 5 times a power of ten, about five
// ticks, the range widened to whole steps. A range of one value is widened around it.
struct AxisLayout {
  double lo = 0.0, hi = 1.0;
  std::vector<AxisTick> ticks;
};
AxisLayout axis_layout(double lo, double hi, AxisScale scale);

// The plot as one <svg> element (no XML declaration, so it can be placed inside HTML). A plot with
// no drawable point says so in its picture instead of drawing axes.
std::string svg_line_plot(const LinePlot& plot);

}  // namespace pathspace::study
