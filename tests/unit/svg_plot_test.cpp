// The study pages' SVG plots (src/pathspace/study/svg_plot.h): the output parses as XML (pugixml),
// log axes tick at the powers of ten that cover the data, linear axes at nice steps, text is
// escaped, points a log axis cannot show are skipped, and a plot without data says so.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <pugixml.hpp>

#include "pathspace/study/svg_plot.h"

namespace {

using namespace pathspace::study;

std::vector<double> tick_values(const AxisLayout& a) {
  std::vector<double> v;
  for (const AxisTick& t : a.ticks) v.push_back(t.value);
  return v;
}

LinePlot convergence_plot() {
  LinePlot p;
  p.title = "relMSE <vs> spp & \"error\"";
  p.x_label = "samples per pixel";
  p.y_label = "relMSE";
  p.x_scale = AxisScale::log;
  p.y_scale = AxisScale::log;
  p.series = {{"PT", {{1, 3.2}, {4, 0.9}, {16, 0.21}, {64, 0.05}}}, {"PT + consistent", {{1, 0.4}, {4, 0.12}, {16, 0.03}, {64, 0.009}}}};
  return p;
}

TEST(SvgPlot, LogTicksArePowersOfTenCoveringTheData) {
  const AxisLayout a = axis_layout(0.009, 3.2, AxisScale::log);
  EXPECT_DOUBLE_EQ(a.lo, 1e-3);
  EXPECT_DOUBLE_EQ(a.hi, 10.0);
  const std::vector<double> expected = {1e-3, 1e-2, 1e-1, 1.0, 10.0};
  ASSERT_EQ(tick_values(a).size(), expected.size());
  for (size_t i = 0; i < expected.size(); ++i) EXPECT_NEAR(a.ticks[i].value, expected[i], expected[i] * 1e-12);
  EXPECT_EQ(a.ticks[0].label, "0.001");
  EXPECT_EQ(a.ticks[4].label, "10");
}

TEST(SvgPlot, NarrowLogRangeAddsTwoAndFive) {
  const AxisLayout a = axis_layout(1.0, 64.0, AxisScale::log);
  EXPECT_DOUBLE_EQ(a.lo, 1.0);
  EXPECT_DOUBLE_EQ(a.hi, 100.0);
  const std::vector<double> expected = {1, 2, 5, 10, 20, 50, 100};
  const std::vector<double> got = tick_values(a);
  ASSERT_EQ(got.size(), expected.size());
  for (size_t i = 0; i < expected.size(); ++i) EXPECT_NEAR(got[i], expected[i], 1e-9);
}

TEST(SvgPlot, ExactPowersOfTenAreNotWidened) {
  const AxisLayout a = axis_layout(1e-4, 1e2, AxisScale::log);
  EXPECT_DOUBLE_EQ(a.lo, 1e-4);
  EXPECT_DOUBLE_EQ(a.hi, 1e2);
  EXPECT_EQ(a.ticks.size(), 7u);
  EXPECT_EQ(a.ticks.front().label, "1e-04");
}

TEST(SvgPlot, LinearTicksAreNiceSteps) {
  const AxisLayout a = axis_layout(3.0, 47.0, AxisScale::linear);
  EXPECT_DOUBLE_EQ(a.lo, 0.0);
  EXPECT_DOUBLE_EQ(a.hi, 50.0);
  const std::vector<double> got = tick_values(a);
  const std::vector<double> expected = {0, 10, 20, 30, 40, 50};
  ASSERT_EQ(got.size(), expected.size());
  for (size_t i = 0; i < expected.size(); ++i) EXPECT_NEAR(got[i], expected[i], 1e-9);
  const AxisLayout one = axis_layout(2.0, 2.0, AxisScale::linear);  // a single value is widened
  EXPECT_LT(one.lo, 2.0);
  EXPECT_GT(one.hi, 2.0);
}

TEST(SvgPlot, IsWellFormedXmlWithEscapedTextAndAllParts) {
  const std::string svg = svg_line_plot(convergence_plot());
  pugi::xml_document doc;
  const pugi::xml_parse_result parsed = doc.load_string(svg.c_str());
  ASSERT_TRUE(parsed) << parsed.description() << "\n" << svg;
  const pugi::xml_node root = doc.child("svg");
  ASSERT_TRUE(root);
  EXPECT_STREQ(root.attribute("xmlns").value(), "http://www.w3.org/2000/svg");
  EXPECT_GT(root.attribute("width").as_int(), 0);
  EXPECT_GT(root.attribute("height").as_int(), 0);
  EXPECT_NE(svg.find("relMSE &lt;vs&gt; spp &amp; &quot;error&quot;"), std::string::npos);
  int polylines = 0, x_ticks = 0, y_ticks = 0;
  std::vector<std::string> texts;
  for (const pugi::xpath_node& n : doc.select_nodes("//polyline")) {
    (void)n;
    ++polylines;
  }
  for (const pugi::xpath_node& n : doc.select_nodes("//text")) {
    const std::string cls = n.node().attribute("class").value();
    x_ticks += cls == "xtick";
    y_ticks += cls == "ytick";
    texts.push_back(n.node().child_value());
  }
  EXPECT_EQ(polylines, 2);
  EXPECT_EQ(x_ticks, 7);  // 1, 2, 5, 10, 20, 50, 100
  EXPECT_EQ(y_ticks, 5);  // 0.001 ... 10
  for (const char* legend : {"PT", "PT + consistent", "samples per pixel", "relMSE"})
    EXPECT_NE(std::find(texts.begin(), texts.end(), legend), texts.end()) << legend;
}

TEST(SvgPlot, SkipsPointsALogAxisCannotShow) {
  LinePlot p = convergence_plot();
  p.series[0].points.push_back({128, 0.0});
  p.series[0].points.push_back({256, std::numeric_limits<double>::quiet_NaN()});
  const std::string svg = svg_line_plot(p);
  pugi::xml_document doc;
  ASSERT_TRUE(doc.load_string(svg.c_str()));
  const std::string first = doc.select_node("//polyline").node().attribute("points").value();
  EXPECT_EQ(std::count(first.begin(), first.end(), ','), 4);  // the 4 positive points only
  EXPECT_EQ(svg.find("nan"), std::string::npos);
  EXPECT_EQ(svg.find("inf"), std::string::npos);
}

TEST(SvgPlot, EmptyPlotSaysSo) {
  LinePlot p;
  p.title = "nothing";
  p.series = {{"empty", {}}};
  const std::string svg = svg_line_plot(p);
  pugi::xml_document doc;
  ASSERT_TRUE(doc.load_string(svg.c_str()));
  EXPECT_NE(svg.find("no data to plot"), std::string::npos);
}

}  // namespace
