// Consistency of light tracing with path tracing (docs/testing.md):
//  - LT renders are bit-identical for 1 and 2 threads and across reruns (fixed-point splatting);
//  - LT and PT estimate the same image on the Cornell variants: per-pixel z-test on mean and
//    variance images. LT cannot sample paths whose vertex next to the camera is a Dirac surface
//    (mirror or glass seen directly: the connection has zero density), so pixels whose camera ray
//    may hit such a surface first are masked out of both images (3x3 sub-pixel probe);
//    Scenes with spheres are compared for direct lighting only (2 segments): PT cannot sample
//    caustics from delta lights at all (gbs_p, gbs_s: E-D-S-L), and samples those from the small
//    area light so rarely (heavy tails, underestimated variance) that the z-test rejects correct
//    LT images (measured: bs_c full length, 48 of 256 pixels, LT brighter on the ceiling). Full
//    path length is compared on the sphere-free masks, glossy floor included (PT with 4x the passes
//    there: its glossy caustics E-D-G-L are heavy-tailed too);
//  - with shading normals that differ from the geometric ones (a test tracer perturbs the hit's
//    shading normal), LT with the adjoint correction (Veach 1997 §5.3) still agrees with PT.
#include <gtest/gtest.h>

#include <fmt/core.h>

#include <cmath>
#include <cstdlib>

#include "pathspace/accel/accel.h"
#include "pathspace/camera/pixel_filter_table.h"
#include "pathspace/integrators/lt/lt_integrator.h"
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

TEST(LtDeterminism, BitIdenticalForOneAndTwoThreadsAndReruns) {
  const Scene scene = make_builtin_scene("gbs_c", 48, 48);
  using testing::with_threads;
  LtSettings s;
  const Rendered one = testing::render_integrator(scene, with_threads(make_render_config("lt", s, 9), 1), 3);
  const Rendered two = testing::render_integrator(scene, with_threads(make_render_config("lt", s, 9), 2), 3);
  const Rendered again = testing::render_integrator(scene, with_threads(make_render_config("lt", s, 9), 2), 3);
  Scene wide = scene;  // many splats per vertex, to more pixels
  wide.camera.filter = make_pixel_filter(PixelFilterKind::gaussian, 1.5f);
  const Rendered g1 = testing::render_integrator(wide, with_threads(make_render_config("lt", s, 9), 1), 2);
  const Rendered g2 = testing::render_integrator(wide, with_threads(make_render_config("lt", s, 9), 2), 2);
  size_t lit = 0;
  for (size_t i = 0; i < one.mean.size(); ++i) {
    ASSERT_EQ(one.mean.pixels[i], two.mean.pixels[i]) << "pixel " << i;
    ASSERT_EQ(one.variance.pixels[i], two.variance.pixels[i]) << "pixel " << i;
    ASSERT_EQ(two.mean.pixels[i], again.mean.pixels[i]) << "pixel " << i;
    ASSERT_EQ(g1.mean.pixels[i], g2.mean.pixels[i]) << "pixel " << i;
    lit += one.mean.pixels[i].r > 0.f;
  }
  EXPECT_GT(lit, one.mean.size() / 2);
}

constexpr int kComparisons = 12;
const double kAlphaImage = testing::sidak(0.01, kComparisons);

void expect_same_image(const Rendered& a, const Rendered& b, const std::string& what) {
  testing::expect_same_image(a, b, what, kAlphaImage, "lt", "pt");
}

uint64_t seed_base() { return testing::test_seed_base(); }

struct CornellCase {
  const char* scene;   // SmallVCM id, or a name for a mask without a built-in id
  unsigned mask;       // LoadCornellBox mask (docs/scenes.md §1)
  int max_segments;  // -1: the scene's (10)
  uint32_t lt_passes, pt_passes;
};

// gtest prints the parameter in test listings (not as "N-byte object <...>").
void PrintTo(const CornellCase& c, std::ostream* os) {
  *os << c.scene << " mask " << c.mask << " max_segments " << c.max_segments;
}

class LtPtAgree : public ::testing::TestWithParam<CornellCase> {};

TEST_P(LtPtAgree, CornellVariant) {
  const CornellCase c = GetParam();
  const Scene scene = make_cornell_box(c.mask, 16, 16);
  const Accel accel(scene);
  const std::vector<bool> mask = specular_first_hit_mask(scene, accel);
  LtSettings lt;
  lt.light_paths = 4096;
  lt.max_segments = c.max_segments;
  PtSettings pt;
  pt.max_segments = c.max_segments;
  Rendered a = testing::render_integrator(scene, make_render_config("lt", lt, seed_base() + 101), c.lt_passes);
  Rendered b = testing::render_integrator(scene, make_render_config("pt", pt, seed_base() + 102), c.pt_passes);
  apply_mask(&a, mask);
  apply_mask(&b, mask);
  expect_same_image(a, b, fmt::format("lt-vs-pt-{}-{}", c.scene, c.max_segments));
}

INSTANTIATE_TEST_SUITE_P(Cornell, LtPtAgree,
                         ::testing::Values(CornellCase{"e_c", 1, -1, 256, 1024}, CornellCase{"e_p", 4, -1, 256, 1024},
                                           CornellCase{"gbs_b", 456, -1, 256, 1024},
                                           CornellCase{"glossy_area", 257, -1, 256, 4096},
                                           CornellCase{"glossy_point", 260, -1, 256, 4096},
                                           CornellCase{"glossy_sun", 258, -1, 256, 4096},
                                           CornellCase{"bs_c", 193, 2, 256, 1024}, CornellCase{"gbs_c", 449, 2, 256, 1024},
                                           CornellCase{"glm_c", 273, 2, 256, 1024}, CornellCase{"gbs_p", 452, 2, 256, 1024},
                                           CornellCase{"gbs_s", 450, 2, 256, 1024}),
                         [](const auto& info) {
                           return testing::test_name(std::string(info.param.scene) + (info.param.max_segments > 0 ? "_direct" : ""));
                         });

// A tracer that replaces the shading normal by a smoothly varying one tilted by up to ~35 degrees
// from the geometric normal (a stand-in for interpolated vertex normals, which meshes do not carry yet).
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

Rendered pt_with_tracer(const Scene& scene, const BumpedTracer& tracer, uint32_t passes, uint64_t seed) {
  const SceneView view = scene.view();
  Film film(view.camera.width, view.camera.height);
  const PtSettings settings;
  for (uint32_t pass = 0; pass < passes; ++pass)
    parallel_for(film.pixel_count(), 64, [&](size_t begin, size_t end) {
      PathCounters counters;
      for (size_t pixel = begin; pixel < end; ++pixel) {
        const Sampler sampler(seed, pixel, pass);
        const Ray ray = view.camera.generate_ray(float(pixel % size_t(view.camera.width)) + sampler.at(dims::kPixelX),
                                                 float(pixel / size_t(view.camera.width)) + sampler.at(dims::kPixelY));
        film.add_sample(uint32_t(pixel), pt_trace_path(view, tracer, sampler, ray, settings, &counters));
      }
    });
  return {film.mean(), film.variance_of_mean()};
}

TEST(LtPtAgreeShadingNormals, BumpedCornellBox) {
  const Scene scene = make_builtin_scene("e_c", 16, 16);
  const Accel accel(scene);
  const BumpedTracer tracer{accel};
  SplatFilm splats(16, 16);
  Film film(16, 16);
  PathCounters counters;
  LtSettings lt;
  lt.light_paths = 4096;
  for (uint32_t pass = 0; pass < 256; ++pass) lt_render_pass(scene.view(), tracer, lt, seed_base() + 201, pass, splats, film, counters);
  const Rendered a{film.mean(), film.variance_of_mean()};
  const Rendered b = pt_with_tracer(scene, tracer, 1024, seed_base() + 202);
  expect_same_image(a, b, "lt-vs-pt-shading-normals");
  // The bumped normals must change the image noticeably, or the test would prove nothing.
  const Rendered flat = testing::render_integrator(scene, make_render_config("pt", PtSettings{}, 0), 1024);
  const testing::ImageZTest z = testing::image_z_test(flat.mean, flat.variance, b.mean, b.variance, 1e-3, kAlphaImage);
  EXPECT_FALSE(z.passed()) << "shading normals had no visible effect";
}

}  // namespace
}  // namespace pathspace
