#include "support/reference_regions.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "support/statistics.h"

namespace pathspace::testing {

namespace {

struct PixelRect {
  int x0, y0, x1, y1;
};

PixelRect to_pixels(const ImageRegion& r, int width, int height) {
  return {int(r.x0 * float(width)), int(r.y0 * float(height)), int(r.x1 * float(width)), int(r.y1 * float(height))};
}

// Two-sided critical value: normal_two_sided_p(z) = alpha, by bisection.
double critical_z(double alpha) {
  double lo = 0.0, hi = 20.0;
  for (int i = 0; i < 100; ++i) ((normal_two_sided_p(0.5 * (lo + hi)) > alpha) ? lo : hi) = 0.5 * (lo + hi);
  return lo;
}

}  // namespace

Rgb region_mean(const Image& img, const ImageRegion& region) {
  const PixelRect p = to_pixels(region, img.width, img.height);
  double sum[3] = {0, 0, 0};
  double n = 0;
  for (int y = p.y0; y < p.y1; ++y)
    for (int x = p.x0; x < p.x1; ++x) {
      const Rgb& c = img.at(x, y);
      if (!all_finite(c)) continue;
      for (int ch = 0; ch < 3; ++ch) sum[ch] += c[ch];
      n += 1;
    }
  if (n == 0) return {};
  return {float(sum[0] / n), float(sum[1] / n), float(sum[2] / n)};
}

Image downsample_box(const Image& reference, int width, int height) {
  EXPECT_EQ(reference.width % width, 0) << "reference width " << reference.width << " is not a multiple of " << width;
  EXPECT_EQ(reference.height % height, 0) << "reference height " << reference.height << " is not a multiple of " << height;
  const int kx = reference.width / width, ky = reference.height / height;
  Image out(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      double sum[3] = {0, 0, 0}, n = 0;
      for (int yy = y * ky; yy < (y + 1) * ky; ++yy)
        for (int xx = x * kx; xx < (x + 1) * kx; ++xx) {
          const Rgb& c = reference.at(xx, yy);
          if (!all_finite(c)) continue;
          for (int ch = 0; ch < 3; ++ch) sum[ch] += c[ch];
          n += 1;
        }
      if (n > 0) out.at(x, y) = Rgb(float(sum[0] / n), float(sum[1] / n), float(sum[2] / n));
    }
  return out;
}

void expect_regions_match_reference(const Rendered& render, const Image& reference, const std::vector<ImageRegion>& regions,
                                    double allowance, double family_alpha) {
  const int w = render.mean.width, h = render.mean.height;
  const Image ref = downsample_box(reference, w, h);
  const double z_crit = critical_z(sidak(family_alpha, int(regions.size()) * 3));
  for (const ImageRegion& g : regions) {
    const PixelRect p = to_pixels(g, w, h);
    const double n = double((p.x1 - p.x0) * (p.y1 - p.y0));
    ASSERT_GT(n, 0) << g.name << " covers no pixel at " << w << "x" << h;
    double var_sum[3] = {0, 0, 0};
    for (int y = p.y0; y < p.y1; ++y)
      for (int x = p.x0; x < p.x1; ++x)
        for (int c = 0; c < 3; ++c) var_sum[c] += render.variance.at(x, y)[c];
    const Rgb ours = region_mean(render.mean, g), theirs = region_mean(ref, g);
    for (int c = 0; c < 3; ++c) {
      const double m = ours[c], rm = theirs[c];
      const double sigma = std::sqrt(var_sum[c] / (n * n) + (allowance * rm) * (allowance * rm));
      const double z = sigma > 0 ? (m - rm) / sigma : 0.0;
      EXPECT_LT(std::fabs(z), z_crit) << g.name << " channel " << c << ": ours " << m << ", reference " << rm;
      std::printf("%-24s ch%d ours %.4f reference %.4f rel %+.2f%% z %+.2f\n", g.name, c, m, rm,
                  rm != 0 ? 100.0 * (m - rm) / rm : 0.0, z);
    }
  }
}

}  // namespace pathspace::testing
