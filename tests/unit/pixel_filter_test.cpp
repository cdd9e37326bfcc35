// The pixel filters (camera/pixel_filter.h): normalised, never negative, sampled with the density
// they evaluate to (chi-square test, alpha = 0.01 Sidak-corrected over the filters), the unit box
// bit-identical to the raw uniform offsets, splat weights that keep one pixel area, and bad
// parameters refused.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "pathspace/base/error.h"
#include "pathspace/camera/pixel_filter_table.h"
#include "pathspace/sampling/rng.h"
#include "support/statistics.h"

namespace pathspace {
namespace {

std::vector<PixelFilter> every_filter() {
  return {make_pixel_filter(PixelFilterKind::box, 0.5f), make_pixel_filter(PixelFilterKind::box, 1.25f),
          make_pixel_filter(PixelFilterKind::tent, 2.f), make_pixel_filter(PixelFilterKind::gaussian, 1.5f, 0.5f),
          make_pixel_filter(PixelFilterKind::mitchell, 2.f), make_pixel_filter(PixelFilterKind::mitchell, 2.f, 0.5f, 0.f, 0.5f)};
}

TEST(PixelFilter, NormalisedAndNeverNegative) {
  for (const PixelFilter& f : every_filter()) {
    SCOPED_TRACE(describe_pixel_filter(f));
    double integral = 0.0;
    const int n = 20000;
    for (int i = 0; i < n; ++i) {
      const double x = -f.radius + (i + 0.5) * 2.0 * f.radius / n;
      const float v = f.eval_1d(float(x));
      EXPECT_GE(v, 0.f);
      integral += v * 2.0 * f.radius / n;
    }
    EXPECT_NEAR(integral, 1.0, 1e-4);
    EXPECT_EQ(f.eval_1d(f.radius), 0.f);
    EXPECT_EQ(f.eval_1d(-f.radius - 0.1f), 0.f);
    EXPECT_EQ(f.cdf[PixelFilter::kBins], 1.f);
  }
}

// Mitchell-Netravali (B = C = 1/3) is 8/9 at the centre and negative between 1 and 2 of its units:
// the table keeps the positive part only.
TEST(PixelFilter, MitchellDropsItsNegativeLobes) {
  const PixelFilter f = make_pixel_filter(PixelFilterKind::mitchell, 2.f);
  EXPECT_GT(f.eval_1d(0.f), f.eval_1d(0.9f));
  EXPECT_EQ(f.eval_1d(1.7f), 0.f);  // 1.7 pixels = 1.7 of Mitchell's units at radius 2: negative there
}

// Offsets drawn by sample_filter_offset fall into 64 equal cells of [-r, r] as often as the filter's
// integral over each cell says (the cells split the table's steps exactly, so the expectation is exact).
TEST(PixelFilter, SamplesFollowTheFilter) {
  const std::vector<PixelFilter> filters = every_filter();
  const double alpha = testing::sidak(0.01, int(filters.size()));
  Pcg32 rng(17, 1);
  for (const PixelFilter& f : filters) {
    SCOPED_TRACE(describe_pixel_filter(f));
    constexpr int kCells = 2 * PixelFilter::kBins;
    const int n = 200000;
    std::vector<int> counts(kCells, 0);
    for (int i = 0; i < n; ++i) {
      const float x = sample_filter_offset(f, rng.next_float());
      ASSERT_LE(std::fabs(x), f.radius);
      ++counts[std::min(kCells - 1, int((x + f.radius) / (2.f * f.radius) * kCells))];
    }
    double chi2 = 0.0;
    int dof = -1;
    for (int c = 0; c < kCells; ++c) {
      const double centre = -f.radius + (c + 0.5) * 2.0 * f.radius / kCells;
      const double expected = n * f.eval_1d(float(centre)) * 2.0 * f.radius / kCells;
      if (expected < 5.0) {
        EXPECT_LE(counts[c], expected > 0.0 ? 20 : 0) << "cell " << c;
        continue;
      }
      chi2 += (counts[c] - expected) * (counts[c] - expected) / expected;
      ++dof;
    }
    EXPECT_GT(testing::chi2_survival(chi2, dof), alpha) << "chi2 " << chi2 << " dof " << dof;
  }
}

TEST(PixelFilter, UnitBoxOffsetsAreTheRawUniformNumbers) {
  const PixelFilter box;  // the camera's default
  EXPECT_TRUE(box.is_unit_box());
  const Point2 p = sample_filter_raster(box, 7, 3, 0.123f, 0.987f);
  EXPECT_EQ(p.x, 7.f + 0.123f);
  EXPECT_EQ(p.y, 3.f + 0.987f);
  EXPECT_TRUE(make_pixel_filter(PixelFilterKind::box, 0.5f).is_unit_box());
}

// A splat anywhere inside the image spreads weights that sum to about one pixel area; far from the
// border the sum over many random points averages to exactly one (the filter integrates to one).
TEST(PixelFilter, SplatWeightsKeepOnePixelArea) {
  Pcg32 rng(5, 1);
  for (const PixelFilter& f : every_filter()) {
    SCOPED_TRACE(describe_pixel_filter(f));
    double total = 0.0;
    const int n = 20000;
    for (int i = 0; i < n; ++i) {
      const float rx = 20.f + 10.f * rng.next_float(), ry = 20.f + 10.f * rng.next_float();
      for_each_filter_pixel(f, 50, 50, rx, ry, [&](uint32_t, float w) { total += w; });
    }
    EXPECT_NEAR(total / n, 1.0, 0.01);
  }
  double outside = 0.0;
  for_each_filter_pixel(make_pixel_filter(PixelFilterKind::gaussian, 1.5f), 8, 8, -0.5f, 4.f, [&](uint32_t p, float w) {
    EXPECT_EQ(p % 8, 0u);  // only the first column is within 1.5 pixels of x = -0.5
    outside += w;
  });
  EXPECT_GT(outside, 0.0);
}

TEST(PixelFilter, BadParametersAreErrors) {
  EXPECT_THROW(make_pixel_filter(PixelFilterKind::tent, 0.f), Error);
  EXPECT_THROW(make_pixel_filter(PixelFilterKind::tent, 17.f), Error);
  EXPECT_THROW(make_pixel_filter(PixelFilterKind::tent, NAN), Error);
  EXPECT_THROW(make_pixel_filter(PixelFilterKind::gaussian, 1.5f, -1.f), Error);
  EXPECT_THROW(make_pixel_filter(PixelFilterKind::mitchell, 2.f, 0.5f, INFINITY, 0.f), Error);
  // B = 0, C = -10 makes Mitchell negative almost everywhere... but not at the centre, so it stays valid.
  EXPECT_NO_THROW(make_pixel_filter(PixelFilterKind::mitchell, 2.f, 0.5f, 0.f, -10.f));
  EXPECT_EQ(parse_pixel_filter_kind("gaussian"), PixelFilterKind::gaussian);
  EXPECT_FALSE(parse_pixel_filter_kind("sinc"));
}

}  // namespace
}  // namespace pathspace
