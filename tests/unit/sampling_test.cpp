// Unit tests: PCG32, the deterministic sampler, warps and their inverses, discrete distributions.
#include <gtest/gtest.h>

#include <set>

#include "pathspace/sampling/discrete.h"
#include "pathspace/sampling/rng.h"
#include "pathspace/sampling/sampler.h"
#include "pathspace/sampling/warps.h"
#include "support/statistics.h"

namespace pathspace {
namespace {

TEST(Pcg32, AdvanceEqualsStepping) {
  Pcg32 a(42, 7), b(42, 7);
  for (int i = 0; i < 1000; ++i) a.next_u32();
  b.advance(1000);
  for (int i = 0; i < 10; ++i) EXPECT_EQ(a.next_u32(), b.next_u32());
}

TEST(Pcg32, FloatsInUnitInterval) {
  Pcg32 rng(1, 2);
  for (int i = 0; i < 100000; ++i) {
    const float u = rng.next_float();
    ASSERT_GE(u, 0.f);
    ASSERT_LT(u, 1.f);
  }
}

TEST(Sampler, PureFunctionOfItsIndices) {
  const Sampler a(7, 1234, 5), b(7, 1234, 5);
  for (uint32_t d = 0; d < 64; ++d) EXPECT_EQ(a.at(d), b.at(d));
  Sampler seq(7, 1234, 5);
  for (uint32_t d = 0; d < 64; ++d) EXPECT_EQ(seq.next_1d(), a.at(d));  // sequential == random access
  // Changing any index changes the numbers.
  const Sampler other_seed(8, 1234, 5), other_pixel(7, 1235, 5), other_sample(7, 1234, 6);
  int same_seed = 0, same_pixel = 0, same_sample = 0;
  for (uint32_t d = 0; d < 64; ++d) {
    same_seed += a.at(d) == other_seed.at(d);
    same_pixel += a.at(d) == other_pixel.at(d);
    same_sample += a.at(d) == other_sample.at(d);
  }
  EXPECT_LE(same_seed, 1);
  EXPECT_LE(same_pixel, 1);
  EXPECT_LE(same_sample, 1);
}

// Chi-square test of uniformity of one dimension across pixels and of pairs of dimensions.
TEST(Sampler, UniformAndPairwiseIndependent) {
  constexpr int kBins = 16, kN = 200000;
  std::vector<double> h1(kBins, 0), h2(kBins * kBins, 0);
  for (int i = 0; i < kN; ++i) {
    const Sampler s(3, uint64_t(i), 0);
    const float u = s.at(4), v = s.at(5);
    ASSERT_GE(u, 0.f);
    ASSERT_LT(u, 1.f);
    h1[int(u * kBins)] += 1;
    h2[int(u * kBins) * kBins + int(v * kBins)] += 1;
  }
  auto chi2 = [](const std::vector<double>& h, double expected) {
    double x = 0;
    for (double o : h) x += (o - expected) * (o - expected) / expected;
    return x;
  };
  const double alpha = testing::sidak(0.01, 2);
  EXPECT_GT(testing::chi2_survival(chi2(h1, double(kN) / kBins), kBins - 1), alpha);
  EXPECT_GT(testing::chi2_survival(chi2(h2, double(kN) / (kBins * kBins)), kBins * kBins - 1), alpha);
}

void expect_near_point(Point2 a, Point2 b, float tol) {
  EXPECT_NEAR(a.x, b.x, tol);
  EXPECT_NEAR(a.y, b.y, tol);
}

TEST(Warps, RoundTrips) {
  Pcg32 rng(11, 3);
  for (int i = 0; i < 10000; ++i) {
    const Point2 u{rng.next_float() * 0.998f + 0.001f, rng.next_float() * 0.998f + 0.001f};
    expect_near_point(disk_concentric_to_square(square_to_disk_concentric(u)), u, 2e-4f);
    expect_near_point(cosine_hemisphere_to_square(square_to_cosine_hemisphere(u)), u, 2e-4f);
    expect_near_point(uniform_sphere_to_square(square_to_uniform_sphere(u)), u, 2e-4f);
    expect_near_point(uniform_hemisphere_to_square(square_to_uniform_hemisphere(u)), u, 2e-4f);
    expect_near_point(uniform_cone_to_square(square_to_uniform_cone(u, 0.7f), 0.7f), u, 2e-3f);
    expect_near_point(power_cosine_to_square(square_to_power_cosine(u, 20.f), 20.f), u, 2e-3f);
    expect_near_point(triangle_barycentric_to_square(square_to_triangle_barycentric(u)), u, 2e-4f);
  }
}

TEST(Warps, DirectionsAreUnitAndInDomain) {
  Pcg32 rng(5, 9);
  for (int i = 0; i < 10000; ++i) {
    const Point2 u{rng.next_float(), rng.next_float()};
    EXPECT_NEAR(length(square_to_cosine_hemisphere(u)), 1.f, 1e-5f);
    EXPECT_GE(square_to_cosine_hemisphere(u).z, 0.f);
    EXPECT_NEAR(length(square_to_uniform_sphere(u)), 1.f, 1e-5f);
    EXPECT_GE(square_to_uniform_cone(u, 0.9f).z, 0.9f - 1e-6f);
    const Point2 b = square_to_triangle_barycentric(u);
    EXPECT_GE(b.x, 0.f);
    EXPECT_GE(b.y, 0.f);
    EXPECT_LE(b.x + b.y, 1.f + 1e-6f);
  }
}

TEST(Discrete, SamplesByWeightAndSkipsZeros) {
  DiscreteDistribution d({1.f, 0.f, 3.f, 0.f});
  const DiscreteView v = d.view();
  EXPECT_FLOAT_EQ(v.probability(0), 0.25f);
  EXPECT_FLOAT_EQ(v.probability(1), 0.f);
  EXPECT_FLOAT_EQ(v.probability(2), 0.75f);
  float p;
  EXPECT_EQ(v.sample(0.f, &p), 0u);
  EXPECT_EQ(v.sample(0.2499f, &p), 0u);
  EXPECT_EQ(v.sample(0.25f, &p), 2u);
  EXPECT_FLOAT_EQ(p, 0.75f);
  EXPECT_EQ(v.sample(0.99999f, &p), 2u);
}

}  // namespace
}  // namespace pathspace
