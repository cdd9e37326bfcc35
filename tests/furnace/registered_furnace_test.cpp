// Every registered integrator, alone and with every filter it composes with, taken from the
// registries (integrators/integrator_registry.h, filters/filter_registry.h) at run time: a new
// integrator or filter is tested here by registering it, with its default options.
//  * Furnace: the inside of an emissive diffuse sphere (support/test_scenes.h), L = Le / (1 - a) in
//    every pixel. A density estimate on a sphere is unbiased for every radius (the part of a sphere
//    within distance r of a point on it has area pi r^2), and averaging vertices whose contributions
//    share one expectation keeps it, so every pair must meet the closed form. A pass's pixels are
//    correlated (shared photons, voxel averages), so the samples of the t-test are whole passes of
//    independent seeds. alpha = 0.01, Sidak-corrected over the pairs. With 160 passes at 32x32 every
//    pair's standard error is at most 0.35% of L: each fails when the expectation is off by 2%.
//  * Thread count: two passes of the Cornell box with 1 and with 2 threads give the same image bit
//    for bit (docs/architecture.md: every random number is a function of seed, pixel and dimension).
#include <gtest/gtest.h>

#include <algorithm>
#include <ostream>
#include <string>
#include <vector>

#include "pathspace/accel/accel.h"
#include "pathspace/scene/builtin_scenes.h"
#include "pathspace/session/render.h"
#include "support/statistics.h"
#include "support/test_scenes.h"

namespace pathspace {
namespace {

struct Pair {
  std::string integrator, filter;  // filter "none": no path space filter
};
// GoogleTest prints a parameter of a failing test with this.
[[maybe_unused]] void PrintTo(const Pair& p, std::ostream* out) { *out << p.integrator << " + " << p.filter; }

std::vector<Pair> registered_pairs() {
  std::vector<Pair> pairs;
  for (const IntegratorEntry& e : integrator_registry().entries()) {
    pairs.push_back({e.name, FilterChoice::kNone});
    for (const std::string& f : e.filter_names()) pairs.push_back({e.name, f});
  }
  return pairs;
}

std::string pair_name(const ::testing::TestParamInfo<Pair>& info) { return info.param.integrator + "_" + info.param.filter; }

RenderConfig default_config(const Pair& p, uint64_t seed, int threads) {
  RenderConfig c = configure_render(p.integrator, p.filter, OptionValues{});
  c.seed = seed;
  c.threads = threads;
  return c;
}

double image_mean(const Image& image) {
  double sum = 0.0;
  for (const Rgb& v : image.pixels) sum += double(v.r) + double(v.g) + double(v.b);
  return sum / (3.0 * double(image.size()));
}

class RegisteredPairs : public ::testing::TestWithParam<Pair> {};

TEST(RegistryCoverage, TheRegistriesListEveryIntegratorAndFilter) {
  // Guards the parameterised tests below against an empty registry (nothing would be tested).
  std::vector<std::string> integrators, filters;
  for (const Pair& p : registered_pairs()) {
    integrators.push_back(p.integrator);
    filters.push_back(p.filter);
  }
  for (const char* name : {"pt", "lt", "bpt", "sppm", "pclt"})
    EXPECT_NE(std::find(integrators.begin(), integrators.end(), name), integrators.end()) << name;
  for (const char* name : {"hashed", "consistent"})
    EXPECT_NE(std::find(filters.begin(), filters.end(), name), filters.end()) << name;
}

TEST_P(RegisteredPairs, EmissiveSphereFurnace) {
  const float le = 0.5f, albedo = 0.5f;
  const Scene scene = testing::make_emissive_sphere(2.f, le, albedo, 32);
  const Accel accel(scene);
  constexpr int kSeeds = 160;
  const double alpha = testing::sidak(0.01, int(registered_pairs().size()));
  double sum = 0.0, sum_sq = 0.0;
  for (int seed = 0; seed < kSeeds; ++seed) {
    const RenderSnapshot shot = render(scene, accel, default_config(GetParam(), 1000 + uint64_t(seed), 0), RunLimit::for_passes(1));
    const double m = image_mean(shot.mean);
    sum += m;
    sum_sq += m * m;
  }
  const double expected = le / (1.0 - albedo);
  const testing::MeanTest t = testing::t_test_mean(sum, sum_sq, kSeeds, expected);
  EXPECT_GT(t.p, alpha) << "mean " << t.mean << " +- " << t.std_error << " (expected " << expected << ", t = " << t.t << ")";
}

TEST_P(RegisteredPairs, ImageIsTheSameForAnyThreadCount) {
  const Scene scene = make_builtin_scene("cornell-box", 24, 24);
  const Accel accel(scene);
  const RenderSnapshot one = render(scene, accel, default_config(GetParam(), 7, 1), RunLimit::for_passes(2));
  const RenderSnapshot two = render(scene, accel, default_config(GetParam(), 7, 2), RunLimit::for_passes(2));
  ASSERT_EQ(one.mean.size(), two.mean.size());
  size_t differing = 0;
  for (size_t i = 0; i < one.mean.size(); ++i) {
    const Rgb a = one.mean.pixels[i], b = two.mean.pixels[i];
    differing += a.r != b.r || a.g != b.g || a.b != b.b;
  }
  EXPECT_EQ(differing, 0u) << "pixels that differ between 1 and 2 threads";
}

INSTANTIATE_TEST_SUITE_P(Registry, RegisteredPairs, ::testing::ValuesIn(registered_pairs()), pair_name);

}  // namespace
}  // namespace pathspace
