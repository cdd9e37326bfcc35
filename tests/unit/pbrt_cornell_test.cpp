// The real pbrt-v4 Cornell box from ../shared/scenes/bitterli/cornell-box: it loads with the expected
// geometry, lights and camera, and renders without NaN to diffuse-wall brightnesses that agree with
// Bitterli's Tungsten reference (TungstenRender.exr) in a per-region z-test. Skipped when the shared
// scenes folder is absent.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "pathspace/accel/accel.h"
#include "pathspace/film/film.h"
#include "pathspace/integrators/render.h"
#include "pathspace/io/image_io.h"
#include "pathspace/io/scene_loader.h"

namespace pathspace {
namespace {

#ifndef PATHSPACE_SHARED_SCENES_DIR
#define PATHSPACE_SHARED_SCENES_DIR ""
#endif

std::string cornell_dir() { return std::string(PATHSPACE_SHARED_SCENES_DIR) + "/bitterli/cornell-box"; }

#define REQUIRE_CORNELL()                                                                          \
  if (!std::filesystem::exists(cornell_dir() + "/scene-v4.pbrt")) GTEST_SKIP() << "no " << cornell_dir()

TEST(PbrtCornellBox, GeometryLightsCamera) {
  REQUIRE_CORNELL();
  std::vector<std::string> warnings;
  SceneFileSettings settings;
  const Scene s = load_scene(cornell_dir() + "/scene-v4.pbrt", {}, &warnings, &settings);
  EXPECT_EQ(s.triangles.size(), 36u);  // 5 walls x 2 + 2 boxes x 12 + light x 2
  EXPECT_EQ(s.spheres.size(), 0u);
  ASSERT_EQ(s.lights.size(), 2u);
  for (const Light& l : s.lights) {
    EXPECT_EQ(l.type, LightType::area_triangle);
    EXPECT_EQ(l.value, Rgb(17, 12, 4));
    const Triangle& t = s.triangles[l.shape];
    EXPECT_NEAR(triangle_normal(s.positions[t.v[0]], s.positions[t.v[1]], s.positions[t.v[2]]).y, -1.f, 1e-5f);  // emits down
  }
  EXPECT_EQ(s.camera.width, 1024);
  EXPECT_EQ(s.camera.height, 1024);
  EXPECT_NEAR(distance(s.camera.position, Vec3(0, 1, 6.8f)), 0.f, 1e-6f);
  EXPECT_NEAR(s.camera.forward.z, -1.f, 1e-6f);
  EXPECT_NEAR(s.camera.right.x, 1.f, 1e-6f);  // the red wall (x = -1) is on the left
  EXPECT_NEAR(s.camera.tan_x, std::tan(19.5 * M_PI / 360.0), 1e-6);
  EXPECT_EQ(s.max_path_segments, 66);  // maxdepth 65 bounces
  EXPECT_EQ(settings.spp, 64);
  EXPECT_EQ(settings.image_name, "cornell-box.png");
  ASSERT_EQ(warnings.size(), 1u);  // only the triangle pixel filter is unsupported
  EXPECT_NE(warnings[0].find("scene-v4.pbrt:6:1: warning: PixelFilter \"triangle\""), std::string::npos) << warnings[0];
}

struct Region {
  const char* name;
  float x0, y0, x1, y1;  // fractions of the image
};

TEST(PbrtCornellBox, RenderMatchesTungstenOnDiffuseWalls) {
  REQUIRE_CORNELL();
  constexpr int kRes = 128;
  SceneLoadOptions o;
  o.width = o.height = kRes;
  Scene scene = load_scene(cornell_dir() + "/scene-v4.pbrt", o, nullptr);
  Accel accel(scene);
  Film film(kRes, kRes);
  RenderRequest req;
  req.spp = 32;
  req.settings.seed = 7;
  const RenderStats stats = render(scene, accel, req, film);
  EXPECT_EQ(stats.dropped_samples, 0u);
  const Image mean = film.mean(), var = film.variance_of_mean();
  for (const Rgb& c : mean.pixels) ASSERT_TRUE(all_finite(c));

  const Image ref = read_image(cornell_dir() + "/TungstenRender.exr");
  ASSERT_EQ(ref.width % kRes, 0);
  const int k = ref.width / kRes;  // box-downsample the reference to our pixel grid
  const Region regions[] = {{"back wall", 0.55f, 0.25f, 0.75f, 0.45f},
                            {"back wall upper left", 0.2f, 0.15f, 0.4f, 0.3f},
                            {"red wall", 0.03f, 0.3f, 0.12f, 0.6f},
                            {"green wall", 0.89f, 0.3f, 0.97f, 0.6f}};
  // Šidák: 4 regions x 3 channels at family-wise alpha = 1e-3.
  const double alpha = 1.0 - std::pow(1.0 - 1e-3, 1.0 / 12.0);
  double lo = 0.0, hi = 10.0;  // two-sided critical z: erfc(z / sqrt 2) = alpha
  for (int i = 0; i < 100; ++i) ((std::erfc(0.5 * (lo + hi) / std::sqrt(2.0)) > alpha) ? lo : hi) = 0.5 * (lo + hi);
  const double z_crit = lo;
  for (const Region& r : regions) {
    const int x0 = int(r.x0 * kRes), x1 = int(r.x1 * kRes), y0 = int(r.y0 * kRes), y1 = int(r.y1 * kRes);
    double sum[3] = {0, 0, 0}, var_sum[3] = {0, 0, 0}, ref_sum[3] = {0, 0, 0};
    const double n = double((x1 - x0) * (y1 - y0));
    for (int y = y0; y < y1; ++y)
      for (int x = x0; x < x1; ++x) {
        for (int c = 0; c < 3; ++c) {
          sum[c] += mean.at(x, y)[c];
          var_sum[c] += var.at(x, y)[c];
        }
        for (int yy = y * k; yy < (y + 1) * k; ++yy)
          for (int xx = x * k; xx < (x + 1) * k; ++xx)
            for (int c = 0; c < 3; ++c) ref_sum[c] += ref.at(xx, yy)[c] / double(k * k);
      }
    for (int c = 0; c < 3; ++c) {
      const double m = sum[c] / n, rm = ref_sum[c] / n;
      // Our noise (variance of the region mean) plus a 2% allowance for what differs by design:
      // Tungsten's tent filter and spectral-vs-RGB details, and the reference's own noise.
      const double sigma = std::sqrt(var_sum[c] / (n * n) + (0.02 * rm) * (0.02 * rm));
      const double z = (m - rm) / sigma;
      EXPECT_LT(std::fabs(z), z_crit) << r.name << " channel " << c << ": ours " << m << ", Tungsten " << rm;
      std::printf("%-22s ch%d ours %.4f tungsten %.4f rel %+.3f%% z %+.2f\n", r.name, c, m, rm, 100.0 * (m - rm) / rm, z);
    }
  }
}

}  // namespace
}  // namespace pathspace
