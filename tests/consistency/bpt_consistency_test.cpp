// Consistency of bidirectional path tracing (docs/testing.md):
//  - BPT renders are bit-identical for 1 and 2 threads and across reruns (fixed-point splats; the
//    light subpath of a pixel draws from its own sampler stream), strategy images included;
//  - BPT agrees with PT (per-pixel z-test on mean and variance images) where PT is a valid reference,
//    for the reasons given in lt_pt_consistency_test.cpp: the sphere-free Cornell masks at full path
//    length, and the sphere scenes for direct lighting (2 segments), where PT has no heavy tails.
//    BPT needs no mask: its camera subpath samples mirror and glass seen directly;
//  - BPT agrees with LT at full length on the sphere scenes, where PT cannot sample caustics from
//    delta lights (gbs_s, gbs_p: E-D-S-L) and samples those from the small area light too rarely;
//    LT cannot see Dirac surfaces directly, so pixels whose camera ray may hit one are masked
//    (gbs_b adds the environment light at full length: infinite-light MIS terms);
//  - the balance and power heuristics give the same image (MIS weights only move noise);
//  - with shading normals that differ from the geometric ones, BPT (adjoint factor on the light
//    subpath, Veach 1997 §5.3; MIS densities in geometric-normal measure) still agrees with PT.
#include <gtest/gtest.h>

#include <fmt/core.h>

#include <cmath>
#include <cstdlib>

#include "pathspace/accel/accel.h"
#include "pathspace/integrators/bpt/bpt_integrator.h"
#include "pathspace/integrators/pt/pt_kernel.h"
#include "pathspace/io/image_io.h"
#include "pathspace/parallel/parallel_for.h"
#include "pathspace/scene/builtin_scenes.h"
#include "support/integrator_comparison.h"
#include "support/statistics.h"
#include "support/test_names.h"

namespace pathspace {
namespace {

using testing::apply_mask;
using testing::Rendered;
using testing::specular_first_hit_mask;

TEST(BptDeterminism, BitIdenticalForOneAndTwoThreadsAndReruns) {
  const Scene scene = make_builtin_scene("gbs_c", 48, 48);
  using testing::with_threads;
  BptSettings s;
  s.strategy_images = 3;
  const RenderConfig config = make_render_config("bpt", s, 9);
  std::vector<NamedImage> aovs1, aovs2;
  const Rendered one = testing::render_integrator(scene, with_threads(config, 1), 3, &aovs1);
  const Rendered two = testing::render_integrator(scene, with_threads(config, 2), 3, &aovs2);
  const Rendered again = testing::render_integrator(scene, with_threads(config, 2), 3);
  size_t lit = 0;
  for (size_t i = 0; i < one.mean.size(); ++i) {
    ASSERT_EQ(one.mean.pixels[i], two.mean.pixels[i]) << "pixel " << i;
    ASSERT_EQ(one.variance.pixels[i], two.variance.pixels[i]) << "pixel " << i;
    ASSERT_EQ(two.mean.pixels[i], again.mean.pixels[i]) << "pixel " << i;
    lit += one.mean.pixels[i].r > 0.f;
  }
  EXPECT_GT(lit, one.mean.size() / 2);
  ASSERT_EQ(aovs1.size(), size_t(bpt_strategy_count(3)));
  ASSERT_EQ(aovs1.size(), aovs2.size());
  for (size_t a = 0; a < aovs1.size(); ++a)
    for (size_t i = 0; i < one.mean.size(); ++i) ASSERT_EQ(aovs1[a].image.pixels[i], aovs2[a].image.pixels[i]) << aovs1[a].name;
}

constexpr int kComparisons = 17;  // image comparisons in this file
const double kAlphaImage = testing::sidak(0.01, kComparisons);

void expect_same_image(const Rendered& a, const Rendered& b, const std::string& what) {
  testing::expect_same_image(a, b, what, kAlphaImage, "a", "b");
}

uint64_t seed_base() { return testing::test_seed_base(); }

struct CornellCase {
  const char* scene;  // SmallVCM id, or a name for a mask without a built-in id
  unsigned mask;      // LoadCornellBox mask (docs/scenes.md §1)
  int max_segments;   // -1: the scene's (10)
  uint32_t bpt_passes, other_passes;
};

std::string case_name(const ::testing::TestParamInfo<CornellCase>& info) {
  return testing::test_name(std::string(info.param.scene) + (info.param.max_segments > 0 ? "_direct" : ""));
}

// gtest prints the parameter in test listings (not as "N-byte object <...>").
void PrintTo(const CornellCase& c, std::ostream* os) {
  *os << c.scene << " mask " << c.mask << " max_segments " << c.max_segments;
}

class BptPtAgree : public ::testing::TestWithParam<CornellCase> {};

TEST_P(BptPtAgree, CornellVariant) {
  const CornellCase c = GetParam();
  const Scene scene = make_cornell_box(c.mask, 16, 16);
  BptSettings bpt;
  bpt.max_segments = c.max_segments;
  PtSettings pt;
  pt.max_segments = c.max_segments;
  const Rendered a = testing::render_integrator(scene, make_render_config("bpt", bpt, seed_base() + 301), c.bpt_passes);
  const Rendered b = testing::render_integrator(scene, make_render_config("pt", pt, seed_base() + 302), c.other_passes);
  expect_same_image(a, b, fmt::format("bpt-vs-pt-{}-{}", c.scene, c.max_segments));
}

INSTANTIATE_TEST_SUITE_P(Cornell, BptPtAgree,
                         ::testing::Values(CornellCase{"e_c", 1, -1, 512, 1024}, CornellCase{"e_p", 4, -1, 512, 1024},
                                           CornellCase{"glossy_area", 257, -1, 512, 4096},
                                           CornellCase{"glossy_point", 260, -1, 512, 4096},
                                           CornellCase{"glossy_sun", 258, -1, 512, 4096},
                                           CornellCase{"bs_c", 193, 2, 512, 1024}, CornellCase{"gbs_b", 456, 2, 512, 1024},
                                           CornellCase{"glm_c", 273, 2, 512, 1024}, CornellCase{"gbs_p", 452, 2, 512, 1024},
                                           CornellCase{"gbs_s", 450, 2, 512, 1024}),
                         case_name);

class BptLtAgree : public ::testing::TestWithParam<CornellCase> {};

TEST_P(BptLtAgree, CornellVariant) {
  const CornellCase c = GetParam();
  const Scene scene = make_cornell_box(c.mask, 16, 16);
  const Accel accel(scene);
  const std::vector<bool> mask = specular_first_hit_mask(scene, accel);
  BptSettings bpt;
  bpt.max_segments = c.max_segments;
  LtSettings lt;
  lt.light_paths = 4096;
  lt.max_segments = c.max_segments;
  Rendered a = testing::render_integrator(scene, make_render_config("bpt", bpt, seed_base() + 401), c.bpt_passes);
  Rendered b = testing::render_integrator(scene, make_render_config("lt", lt, seed_base() + 402), c.other_passes);
  apply_mask(&a, mask);
  apply_mask(&b, mask);
  expect_same_image(a, b, fmt::format("bpt-vs-lt-{}-{}", c.scene, c.max_segments));
}

INSTANTIATE_TEST_SUITE_P(Cornell, BptLtAgree,
                         ::testing::Values(CornellCase{"gbs_s", 450, -1, 512, 256}, CornellCase{"gbs_p", 452, -1, 512, 256},
                                           CornellCase{"bs_c", 193, -1, 512, 256}, CornellCase{"gbs_c", 449, -1, 512, 256},
                                           CornellCase{"gbs_b", 456, -1, 512, 256}),
                         case_name);

// MIS weights change only the noise: balance and power heuristic images agree (caustics included).
TEST(BptHeuristics, BalanceAndPowerAgree) {
  const Scene scene = make_cornell_box(449, 16, 16);  // gbs_c
  BptSettings power, balance;
  balance.mis = MisHeuristic::balance;
  const Rendered a = testing::render_integrator(scene, make_render_config("bpt", power, seed_base() + 501), 512);
  const Rendered b = testing::render_integrator(scene, make_render_config("bpt", balance, seed_base() + 502), 512);
  expect_same_image(a, b, "bpt-power-vs-balance-gbs_c");
}

// The shading-normal perturbation of lt_pt_consistency_test.cpp: a smoothly varying ns tilted by up
// to ~35 degrees from ng.
struct BumpedTracer {
  const Accel& accel;
  bool intersect(const Ray& ray, SurfaceHit* hit) const {
    if (!accel.intersect(ray, hit)) return false;
    const Vec3& p = hit->p;
    const Vec3 t(0.5f * sinf(7.f * p.x + 1.f), 0.5f * sinf(6.f * p.y + 2.f), 0.5f * sinf(8.f * p.z + 3.f));
    hit->ns = normalize(hit->ng + (t - hit->ng * dot(t, hit->ng)));
    return true;
  }
  bool occluded(const Ray& ray) const { return accel.occluded(ray); }
};

TEST(BptPtAgreeShadingNormals, BumpedCornellBox) {
  const Scene scene = make_builtin_scene("e_c", 16, 16);
  const SceneView view = scene.view();
  const Accel accel(scene);
  const BumpedTracer tracer{accel};
  BptSettings settings;
  BptBuffers buffers(16, 16, settings, bpt_max_segments(settings, view));
  Film bpt_film(16, 16), pt_film(16, 16);
  PathCounters counters;
  for (uint32_t pass = 0; pass < 512; ++pass) bpt_render_pass(view, tracer, settings, seed_base() + 601, pass, buffers, bpt_film, counters);
  const PtSettings pt;
  for (uint32_t pass = 0; pass < 1024; ++pass)
    parallel_for(pt_film.pixel_count(), 64, [&](size_t begin, size_t end) {
      PathCounters local;
      for (size_t pixel = begin; pixel < end; ++pixel) {
        const Sampler sampler(seed_base() + 602, pixel, pass);
        const Ray ray = view.camera.generate_ray(float(pixel % 16) + sampler.at(dims::kPixelX), float(pixel / 16) + sampler.at(dims::kPixelY));
        pt_film.add_sample(uint32_t(pixel), pt_trace_path(view, tracer, sampler, ray, pt, &local));
      }
    });
  expect_same_image({bpt_film.mean(), bpt_film.variance_of_mean()}, {pt_film.mean(), pt_film.variance_of_mean()},
                    "bpt-vs-pt-shading-normals");
}

}  // namespace
}  // namespace pathspace
