// Consistency of pixel cache light tracing (PCLT paper sec. 3-5) with LT and SPPM:
//  - bit-identical renders for 1 and 2 threads (fixed-point splats; records compacted in pixel order);
//  - eye-pass classification: ED paths never enter the cache, every record follows >= 1 non-diffuse
//    bounce, at most one record per pixel, none at all in the all-diffuse box;
//  - e_c, e_p (no spheres, all Lambertian): every PCLT path is ED, i.e. projection, so PCLT and LT
//    estimate the same image (per-pixel z-test, support/statistics.h);
//  - bs_c: on pixels whose camera ray always hits a Lambertian wall (3x3 probes) PCLT is projection
//    only and must equal LT; on pixels that always see the mirror/glass sphere it is the pixel cache
//    (ES+D) plus the ES+L emission added from eye paths, which is exactly SPPM's estimate there for
//    the same radius schedule (both gather f = albedo/pi at the first non-delta eye vertex with the
//    same front-side test; SPPM's direct term is ES+L), so PCLT must equal SPPM with no bias
//    allowance. Mixed pixels (sphere silhouettes) are left out. The ES+L part the paper misses is
//    measured by turning it off (printed; docs/pclt.md);
//  - the visibility shortcuts (sec. 5.3): with the same seed the z-buffer and plane renders differ
//    from the shadow-ray render only where a visibility decision differs; their relMSE is bounded.
#include <gtest/gtest.h>

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>

#include "pathspace/accel/accel.h"
#include "pathspace/camera/pixel_filter_table.h"
#include "pathspace/film/image_metrics.h"
#include "pathspace/integrators/pclt/pclt_integrator.h"
#include "pathspace/integrators/sppm/sppm_settings.h"
#include "pathspace/io/image_io.h"
#include "pathspace/scene/builtin_scenes.h"
#include "pathspace/session/render.h"
#include "support/statistics.h"
#include "support/test_names.h"

namespace pathspace {
namespace {

struct Rendered {
  Image mean, variance;
};

Rendered render_with(const Scene& scene, const Accel& accel, RenderConfig config, uint32_t passes, int threads) {
  config.threads = threads;
  const RenderSnapshot snap = render(scene, accel, config, RunLimit::for_passes(passes));
  return {snap.mean, snap.variance};
}

TEST(PcltDeterminism, BitIdenticalForOneAndTwoThreads) {
  Scene scene = make_builtin_scene("gbs_c", 32, 32);
  const Accel accel(scene);
  PcltSettings s;
  s.light_paths = 20000;
  for (int variant = 0; variant < 2; ++variant) {
    if (variant == 1) {  // the other map, a shortcut, a wide pixel filter and a stochastic store
      s.hash_map = PcltHashMap::stochastic;
      s.visibility = PcltVisibility::plane;
      scene.camera.filter = make_pixel_filter(PixelFilterKind::gaussian, 1.5f);
      s.cache_capacity = 100;
      s.stochastic_store = true;
    }
    const Rendered one = render_with(scene, accel, make_render_config("pclt", s, 9), 3, 1);
    const Rendered two = render_with(scene, accel, make_render_config("pclt", s, 9), 3, 2);
    for (size_t i = 0; i < one.mean.size(); ++i) {
      ASSERT_EQ(one.mean.pixels[i], two.mean.pixels[i]) << "variant " << variant << " pixel " << i;
      ASSERT_EQ(one.variance.pixels[i], two.variance.pixels[i]) << "variant " << variant << " pixel " << i;
    }
  }
}

// The eye pass alone, over every pixel of a few iterations.
TEST(PcltEyePass, EdPathsNeverEnterTheCache) {
  for (const char* id : {"e_c", "gbs_c"}) {
    const Scene scene = make_builtin_scene(id, 32, 32);
    const Accel accel(scene);
    const SceneView view = scene.view();
    const PcltSettings settings;
    size_t stored = 0, ed = 0;
    for (uint32_t pass = 0; pass < 8; ++pass)
      for (uint32_t pixel = 0; pixel < 32 * 32; ++pixel) {
        const Sampler sampler(5, pixel, pass);
        const Ray ray = view.camera.generate_ray(float(pixel % 32) + sampler.at(dims::kPixelX), float(pixel / 32) + sampler.at(dims::kPixelY));
        PathCounters counters;
        PcltEyeResult eye;
        pclt_trace_eye(view, accel, sampler, ray, pixel, settings, view.max_path_segments, &counters, &eye);
        ASSERT_FALSE(eye.stored && eye.first_event_diffuse);
        if (eye.stored) {
          ASSERT_GE(eye.nondiffuse_bounces, 1u) << id << " pixel " << pixel;
          ASSERT_EQ(eye.entry.pixel, pixel);
          ASSERT_GE(eye.entry.segments, 2u);
          // The vertex seen first is the Lambertian one only for ED paths: records lie further on.
          ASSERT_GT(distance_squared(eye.entry.p, eye.first_p), 0.f);
        }
        stored += eye.stored;
        ed += eye.first_event_diffuse;
      }
    EXPECT_GT(ed, size_t(1000)) << id;
    if (std::string(id) == "e_c") EXPECT_EQ(stored, 0u) << "an all-Lambertian scene has no ES+D path";
    else EXPECT_GT(stored, size_t(500)) << "spheres and the glossy floor feed the cache";
  }
}

TEST(PcltCache, AtMostOneRecordPerPixel) {
  const Scene scene = make_builtin_scene("gbs_c", 32, 32);
  const Accel accel(scene);
  PcltSettings s;
  s.light_paths = 1000;
  PcltIntegrator integrator(scene, accel, s, 0);
  EXPECT_EQ(integrator.capacity(), size_t(32 * 32));
  for (uint32_t pass = 0; pass < 4; ++pass) {
    Film film(32, 32);
    PathCounters counters;
    integrator.render_pass(pass, film, counters);
    ASSERT_GT(integrator.record_count(), 0u);
    ASSERT_LE(integrator.record_count(), integrator.capacity());
    std::set<uint32_t> pixels;
    for (size_t i = 0; i < integrator.record_count(); ++i) ASSERT_TRUE(pixels.insert(integrator.records()[i].pixel).second);
  }
  const PcltMemory m = integrator.memory();
  EXPECT_EQ(m.cache, size_t(32 * 32) * sizeof(PixelCacheEntry));
  Statistics details;
  integrator.statistics(details);
  EXPECT_GT(details.number("pclt.memory_bytes"), 0.0) << format_statistics(details);
}

constexpr int kComparisons = 4;
const double kAlphaImage = testing::sidak(0.01, kComparisons);

// Keeps pixels where keep[i]; the others become zero in both images (they cannot fail).
Rendered masked(const Rendered& r, const std::vector<bool>& keep) {
  Rendered out = r;
  for (size_t i = 0; i < keep.size(); ++i)
    if (!keep[i]) out.mean.pixels[i] = out.variance.pixels[i] = Rgb();
  return out;
}

void expect_same_image(const Rendered& a, const Rendered& b, const std::string& what) {
  const testing::ImageZTest z = testing::image_z_test(a.mean, a.variance, b.mean, b.variance, 1e-3, kAlphaImage);
  std::printf("%s: %zu of %zu pixels failed (allowed %zu); means %.5f vs %.5f (z = %.2f)\n", what.c_str(), z.failed, z.pixels,
              z.allowed, z.mean_a, z.mean_b, z.mean_z);
  if (z.passed()) return;
  const std::string dir = testing::evidence_dir();
  ADD_FAILURE() << what << ": " << z.failed << " of " << z.pixels << " pixels differ (at most " << z.allowed
                << " allowed); image means " << z.mean_a << " vs " << z.mean_b << " (z = " << z.mean_z << "); images in " << dir;
  write_image(dir + "/" + what + "-a.exr", a.mean);
  write_image(dir + "/" + what + "-b.exr", b.mean);
}

// 3x3 probes per pixel: 1 = all hit a Lambertian-only surface, 2 = all hit a delta-only surface
// (the spheres), 0 = mixed or emitter.
std::vector<int> first_hit_classes(const Scene& scene, const Accel& accel) {
  const SceneView v = scene.view();
  const int w = v.camera.width, h = v.camera.height;
  std::vector<int> cls(size_t(w) * size_t(h));
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) {
      int diffuse = 0, delta = 0;
      for (int k = 0; k < 9; ++k) {
        SurfaceHit hit;
        const Ray ray = v.camera.generate_ray(float(i) + (0.02f + 0.48f * float(k % 3)), float(j) + (0.02f + 0.48f * float(k / 3)));
        if (!accel.intersect(ray, &hit) || hit.light != kNoLight) continue;
        const Material& m = v.materials[hit.material];
        diffuse += m.type == MaterialType::standard && is_black(m.glossy) && is_black(m.specular);
        delta += !bsdf_has_non_delta(m);
      }
      cls[size_t(i) + size_t(j) * size_t(w)] = diffuse == 9 ? 1 : delta == 9 ? 2 : 0;
    }
  return cls;
}

std::vector<bool> where(const std::vector<int>& cls, int value) {
  std::vector<bool> keep(cls.size());
  for (size_t i = 0; i < cls.size(); ++i) keep[i] = cls[i] == value;
  return keep;
}

class PcltAgreesWithLt : public ::testing::TestWithParam<const char*> {};

TEST_P(PcltAgreesWithLt, EmptyCornellIsAllProjection) {
  const Scene scene = make_builtin_scene(GetParam(), 16, 16);
  const Accel accel(scene);
  PcltSettings pclt;
  pclt.light_paths = 4096;
  LtSettings lt;
  lt.light_paths = 4096;
  const Rendered a = render_with(scene, accel, make_render_config("pclt", pclt, 101), 256, 0);
  const Rendered b = render_with(scene, accel, make_render_config("lt", lt, 102), 256, 0);
  expect_same_image(a, b, fmt::format("pclt-vs-lt-{}", GetParam()));
}

INSTANTIATE_TEST_SUITE_P(Cornell, PcltAgreesWithLt, ::testing::Values("e_c", "e_p"), testing::StringParamName());

TEST(PcltAgreesWithLtAndSppm, CornellBoxWallsAndSpheres) {
  const Scene scene = make_builtin_scene("bs_c", 24, 24);
  const Accel accel(scene);
  const std::vector<int> cls = first_hit_classes(scene, accel);
  const std::vector<bool> walls = where(cls, 1), spheres = where(cls, 2);
  ASSERT_GT(std::count(spheres.begin(), spheres.end(), true), 30);
  PcltSettings pclt;
  pclt.light_paths = 20000;
  // The same radius schedule gives PCLT and SPPM the same expectation (bias included) on sphere
  // pixels, so a large constant radius costs nothing here and keeps the gather noise low.
  pclt.initial_radius = 0.15f;
  pclt.alpha = 1.f;
  LtSettings lt;
  lt.light_paths = 20000;
  SppmSettings sppm;
  sppm.photons = 20000;
  sppm.initial_radius = 0.15f;
  sppm.alpha = 1.f;
  const uint32_t passes = 64;
  const Rendered p = render_with(scene, accel, make_render_config("pclt", pclt, 201), passes, 0);
  const Rendered l = render_with(scene, accel, make_render_config("lt", lt, 202), passes, 0);
  const Rendered s = render_with(scene, accel, make_render_config("sppm", sppm, 203), passes, 0);
  expect_same_image(masked(p, walls), masked(l, walls), "pclt-vs-lt-bs_c-walls");
  expect_same_image(masked(p, spheres), masked(s, spheres), "pclt-vs-sppm-bs_c-spheres");

  // What the paper's PCLT misses (ES+L off): reported, and it must be visible on the spheres only.
  pclt.specular_emission = false;
  const Rendered q = render_with(scene, accel, make_render_config("pclt", pclt, 201), passes, 0);
  double all = 0, missing = 0, sphere_all = 0, sphere_missing = 0, wall_missing = 0;
  for (size_t i = 0; i < cls.size(); ++i) {
    const double d = average(p.mean.pixels[i]) - average(q.mean.pixels[i]);
    all += average(p.mean.pixels[i]);
    missing += d;
    if (spheres[i]) sphere_all += average(p.mean.pixels[i]), sphere_missing += d;
    if (walls[i]) wall_missing += std::fabs(d);
  }
  std::printf("bs_c without ES+L: %.2f%% of the image energy, %.2f%% on sphere pixels\n", 100 * missing / all,
              100 * sphere_missing / sphere_all);
  EXPECT_GT(sphere_missing, 0.0);
  EXPECT_EQ(wall_missing, 0.0) << "ES+L is only seen through the spheres";
}

// Sec. 5.3: same seed, so only visibility decisions differ. Measured on bs_c (4 iterations, docs/pclt.md):
//   z-buffer relMSE 0.10 / 0.093 / 0.084, energy -36% / -33% / -32% at 64^2 / 128^2 / 256^2: with
//     epsilon = 5e-4 of the depth, a jittered depth on a slanted plane (floor, side walls) is
//     behind the projected point about half the time - the paper's "systematic energy loss";
//   plane relMSE 0.0095 / 0.0036 / 0.00098, energy -1.9% / -2.3% / -0.01%: errors at silhouettes
//     (the spheres' tangent planes) and edges only, shrinking with the pixel footprint.
// The bounds are the 64^2 values with 2-3x headroom.
TEST(PcltVisibilityShortcuts, ErrorOnCornellBoxIsBounded) {
  const Scene scene = make_builtin_scene("bs_c", 64, 64);
  const Accel accel(scene);
  PcltSettings s;
  s.light_paths = 20000;
  const Rendered ray = render_with(scene, accel, make_render_config("pclt", s, 301), 8, 0);
  const struct {
    PcltVisibility mode;
    const char* name;
    double max_relmse, max_energy_loss;
  } cases[] = {{PcltVisibility::z_buffer, "z-buffer", 0.25, 0.5}, {PcltVisibility::plane, "plane", 0.03, 0.05}};
  for (const auto& c : cases) {
    s.visibility = c.mode;
    const Rendered shortcut = render_with(scene, accel, make_render_config("pclt", s, 301), 8, 0);
    const ImageError m = image_error(shortcut.mean, ray.mean);
    const double loss = (m.mean_reference - m.mean_image) / m.mean_reference;
    std::printf("%s vs shadow ray: relMSE %.3g, energy %+.3f%%\n", c.name, m.rel_mse, -100 * loss);
    EXPECT_LT(m.rel_mse, c.max_relmse) << c.name;
    EXPECT_LT(std::fabs(loss), c.max_energy_loss) << c.name;
  }
}

}  // namespace
}  // namespace pathspace
