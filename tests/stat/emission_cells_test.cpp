// Emission maps sampled by their brightness within a triangle (lights/emission_cells.h):
//  - the cell arithmetic: a point sampled in a cell is found in that cell again;
//  - the cells are drawn by their weights (chi-square over the cells) and the density integrates
//    to one over the triangle (a t-test of its mean at uniform points);
//  - light paths start where NEE would sample: sample_emission's pdf_a is emission_pdf's at the point;
//  - next event estimation of the irradiance under a quad whose map has a small bright spot is
//    unbiased with cells and without them (t-tests against quadrature), and the cells cut its
//    variance (the reason for them);
//  - which triangles get cells (Scene::finalize, scene/emission_cells_build.h).
// Significance: alpha = 0.01 for the file, Sidak-corrected over its kTests hypothesis tests.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "pathspace/lights/emission_cells.h"
#include "pathspace/sampling/rng.h"
#include "pathspace/scene/light_emission.h"
#include "pathspace/scene/scene.h"
#include "pathspace/scene/texture.h"
#include "support/chi2.h"
#include "support/statistics.h"

namespace pathspace {
namespace {

constexpr int kTests = 4;
const double kAlpha = testing::sidak(0.01, kTests);
const Rgb kValue(1.f, 0.8f, 0.6f);

// 32 x 32 texels: a dim gradient and a bright 3 x 3 spot (the lamp of a sign, a screen's highlight).
ImageTexture spot_map() {
  ImageTexture t;
  t.name = "spot map";
  t.width = t.height = 32;
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x) {
      const bool spot = x >= 20 && x < 23 && y >= 9 && y < 12;
      t.texels.push_back(spot ? Rgb(60.f, 50.f, 40.f) : Rgb(0.02f + 0.002f * float(x), 0.03f, 0.01f + 0.001f * float(y)));
    }
  return t;
}

// A 2 x 2 quad at z = 0 emitting downwards (-z), uv the unit square (u along x, v along y).
Scene mapped_quad(ImageTexture map) {
  Scene s;
  const uint32_t black = s.add_material(make_diffuse(Rgb(0.f)));
  const Point2 uv[4] = {{0, 0}, {0, 1}, {1, 1}, {1, 0}};  // counter-clockwise around -z
  auto corner = [&](int k) { return Vec3(2.f * uv[k].x - 1.f, 2.f * uv[k].y - 1.f, 0.f); };
  s.add_quad(corner(0), corner(1), corner(2), corner(3), black, kValue);
  s.uvs.clear();
  for (const int k : {0, 1, 2, 2, 3, 0}) s.uvs.push_back(uv[k]);
  const int32_t tex = int32_t(s.add_texture(std::move(map)));
  for (Light& l : s.lights) l.texture = tex;
  s.camera = make_perspective_camera(Vec3(0, 0, -3), Vec3(0, 0, 1), Vec3(0, 1, 0), 45.f, 8, 8);
  s.finalize();
  return s;
}

// Draws n's cells by a random pmf, lands each sample in its cell.
TEST(EmissionCells, ASampledPointLiesInItsCell) {
  for (const uint32_t n : {2u, 3u, 7u, 16u}) {
    std::vector<float> cells(emission_cell_floats(n));
    Pcg32 rng(n, 5);
    std::vector<float> w(emission_cell_count(n));
    for (uint32_t c = 0; c < w.size(); ++c) w[c] = emission_cell_inside(n, c) ? 0.1f + rng.next_float() : 0.f;
    const DiscreteDistribution d(w);
    std::copy(d.view().pmf, d.view().pmf + d.size(), cells.begin());
    std::copy(d.view().cdf, d.view().cdf + d.size() + 1, cells.begin() + d.size());
    int misplaced = 0;
    for (int i = 0; i < 20000; ++i) {
      const Point2 u{rng.next_float(), rng.next_float()};
      float density;
      const Point2 b = sample_emission_cells(cells.data(), n, u, &density);
      const uint32_t cell = emission_cell_distribution(cells.data(), n).sample(u.x, &density);
      ASSERT_TRUE(b.x >= -1e-6f && b.y >= -1e-6f && b.x + b.y <= 1.f + 1e-6f) << "off the triangle";
      if (emission_cell_at(n, b) != cell) ++misplaced;  // only a rounding step from an edge
    }
    EXPECT_LE(misplaced, 20) << "n " << n;
  }
}

TEST(EmissionCells, CellsFollowTheirWeightsAndTheDensityIntegratesToOne) {  // 2 tests
  const Scene s = mapped_quad(spot_map());
  const SceneView v = s.view();
  const Light& l = s.lights[0];
  ASSERT_EQ(l.emission_grid, 16u);
  const uint32_t n = l.emission_grid;
  const float* cells = v.emission_cells + l.emission_cells;
  const DiscreteView d = emission_cell_distribution(cells, n);
  const int samples = 400000;
  std::vector<double> observed(d.n, 0.0), expected(d.n, 0.0);
  Pcg32 rng(11, 3);
  for (int i = 0; i < samples; ++i) {
    float density;
    const Point2 b = sample_emission_cells(cells, n, {rng.next_float(), rng.next_float()}, &density);
    observed[emission_cell_at(n, b)] += 1.0;
  }
  for (uint32_t c = 0; c < d.n; ++c) expected[c] = double(d.probability(c)) * samples;
  const testing::Chi2Result r = testing::chi2_test(observed, expected);
  std::printf("cells chi2 %.1f dof %.0f p %.4f\n", r.statistic, r.dof, r.p_value);
  EXPECT_TRUE(r.passed(kAlpha)) << "chi2 " << r.statistic << " dof " << r.dof << " p " << r.p_value << " " << r.error;

  double sum = 0.0, sum_sq = 0.0;
  for (int i = 0; i < samples; ++i) {
    const Point2 b = square_to_triangle_barycentric({rng.next_float(), rng.next_float()});
    const double f = emission_cells_density(cells, n, b);
    sum += f;
    sum_sq += f * f;
  }
  const testing::MeanTest t = testing::t_test_mean(sum, sum_sq, samples, 1.0);
  EXPECT_GE(t.p, kAlpha) << "mean density " << t.mean << " +- " << t.std_error;
}

TEST(EmissionCells, LightPathsStartWithTheDensityMisAsksFor) {
  const Scene s = mapped_quad(spot_map());
  const SceneView v = s.view();
  Pcg32 rng(4, 9);
  int checked = 0, differ = 0;
  for (int i = 0; i < 20000; ++i) {
    const Light& l = s.lights[size_t(i % 2)];
    EmissionSample e;
    if (!sample_emission(v, l, 0.f, {rng.next_float(), rng.next_float()}, {rng.next_float(), rng.next_float()}, &e)) continue;
    float pdf_a, pdf_w;
    emission_pdf(v, l, e.p, e.ng, e.d, 0.f, &pdf_a, &pdf_w);
    ++checked;
    if (!(std::fabs(pdf_a - e.pdf_a) <= 1e-4f * e.pdf_a) || !(std::fabs(pdf_w - e.pdf_w) <= 1e-4f * e.pdf_w)) ++differ;
  }
  EXPECT_GT(checked, 19000);
  EXPECT_LE(differ, checked / 1000) << "points a rounding step from a cell edge may take the neighbour's density";
}

// NEE of the irradiance at a point under the quad, with the map's cells and by area.
TEST(EmissionCells, NextEventEstimatesAreUnbiasedAndTheCellsCutTheVariance) {  // 2 tests
  const Scene s = mapped_quad(spot_map());
  const SceneView v = s.view();
  const TextureView map = s.textures[0].view();
  const Vec3 ref(0.3f, -0.2f, -0.8f), up(0, 0, 1);
  // Quadrature over the quad: 1024^2 midpoints of its uv square.
  const int q = 1024;
  double exact = 0.0;
  for (int j = 0; j < q; ++j)
    for (int i = 0; i < q; ++i) {
      const Point2 uv{(float(i) + 0.5f) / q, (float(j) + 0.5f) / q};
      const Vec3 p(2.f * uv.x - 1.f, 2.f * uv.y - 1.f, 0.f), d = p - ref;
      const double d2 = double(length_squared(d)), c = double(d.z) / std::sqrt(d2);
      exact += double(luminance(kValue * texture_lookup(map, uv))) * c * c / d2 * (4.0 / (double(q) * q));
    }
  const int samples = 200000;
  double variance[2] = {0.0, 0.0};
  for (const int use_cells : {1, 0}) {
    Pcg32 rng(21, uint64_t(use_cells));
    double sum = 0.0, sum_sq = 0.0;
    for (int i = 0; i < samples; ++i) {
      double f = 0.0;
      for (Light l : s.lights) {
        if (!use_cells) l.emission_grid = 0;
        LightSample ls;
        if (sample_light(v, l, ref, 0.f, {rng.next_float(), rng.next_float()}, &ls))
          f += double(luminance(ls.li)) * double(fmaxf(0.f, dot(ls.wi, up))) / double(ls.pdf_w);
      }
      sum += f;
      sum_sq += f * f;
    }
    const testing::MeanTest t = testing::t_test_mean(sum, sum_sq, samples, exact);
    variance[use_cells] = sum_sq / samples - (sum / samples) * (sum / samples);
    std::printf("%s: irradiance %.5f +- %.5f, quadrature %.5f, variance %.4g\n", use_cells ? "cells" : "by area", t.mean,
                t.std_error, exact, variance[use_cells]);
    EXPECT_GE(t.p, kAlpha) << (use_cells ? "cells" : "by area") << ": " << t.mean << " +- " << t.std_error << " vs " << exact;
  }
  EXPECT_GT(variance[0], 20.0 * variance[1]) << "the cells must find the spot";
}

TEST(EmissionCells, OnlyMappedTrianglesWithEnoughTexelsGetCells) {
  EXPECT_EQ(mapped_quad(spot_map()).lights[0].emission_grid, 16u);
  ImageTexture flat = spot_map();
  for (Rgb& t : flat.texels) t = Rgb(0.5f);
  EXPECT_EQ(mapped_quad(flat).lights[0].emission_grid, 0u) << "a uniform map keeps area sampling";
  ImageTexture tiny = spot_map();
  tiny.width = tiny.height = 2;
  tiny.texels.resize(4);
  EXPECT_EQ(mapped_quad(tiny).lights[1].emission_grid, 0u) << "2 texels per triangle: no cells";
  ImageTexture small = spot_map();
  small.width = small.height = 8;
  small.texels.resize(64);
  small.texels[9] = Rgb(30.f);
  EXPECT_EQ(mapped_quad(small).lights[0].emission_grid, 4u) << "32 texels per triangle: 4 x 4 cells";
}

}  // namespace
}  // namespace pathspace
