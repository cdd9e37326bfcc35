// Unit tests: the pinhole camera's raster mapping against docs/scenes.md §2 check values,
// the inverse mapping, and the importance / pdf normalisation.
#include <gtest/gtest.h>

#include "pathspace/math/frame.h"
#include "pathspace/sampling/rng.h"
#include "pathspace/scene/builtin_scenes.h"

namespace pathspace {
namespace {

void expect_dir(const Vec3& d, const Vec3& expected) {
  EXPECT_NEAR(d.x, expected.x, 2e-6f);
  EXPECT_NEAR(d.y, expected.y, 2e-6f);
  EXPECT_NEAR(d.z, expected.z, 2e-6f);
}

TEST(PerspectiveCamera, CornellCheckValues) {
  const Scene scene = make_builtin_scene("cornell-box", 512, 512);
  const PerspectiveCamera& c = scene.camera;
  expect_dir(c.direction(0.f, 0.f), Vec3(-0.3513228f, 0.8834083f, 0.3101000f));
  expect_dir(c.direction(256.f, 256.f), Vec3(0.00688625313f, 0.998505473f, -0.0542161278f));
  expect_dir(c.direction(512.f, 512.f), Vec3(0.3632062f, 0.8397255f, -0.4036613f));
  expect_dir(c.direction(0.5f, 0.5f), Vec3(-0.3507998f, 0.8838063f, 0.3095574f));
  expect_dir(c.right, Vec3(0.99997622f, -0.00689640f, 0.f));
  expect_dir(c.up, Vec3(0.00037390f, 0.05421484f, 0.99852922f));
  // SmallVCM's image plane distance W / (2 tan(hfov/2)): one pixel has area 1 there.
  EXPECT_NEAR(1.f / std::sqrt(c.pixel_area()), 618.0387f, 1e-3f);
}

TEST(PerspectiveCamera, RasterRoundTrip) {
  const PerspectiveCamera c = make_perspective_camera(Vec3(1, 2, 3), Vec3(0.2f, 1, -0.1f), Vec3(0, 0, 1), 60.f, 320, 200);
  Pcg32 rng(1, 1);
  for (int i = 0; i < 10000; ++i) {
    const float rx = rng.next_float() * 320.f, ry = rng.next_float() * 200.f;
    float x, y;
    ASSERT_TRUE(c.raster_from_direction(c.direction(rx, ry), &x, &y));
    EXPECT_NEAR(x, rx, 2e-3f);
    EXPECT_NEAR(y, ry, 2e-3f);
  }
  float x, y;
  EXPECT_FALSE(c.raster_from_direction(-c.forward, &x, &y));  // behind
  EXPECT_FALSE(c.raster_from_direction(normalize(c.forward + c.right * 10.f), &x, &y));  // outside
}

// pdf_direction integrates to 1 over the image's solid angle and importance integrates to
// 1 over one pixel's directions (Monte Carlo over uniform directions in a cone covering the image).
TEST(PerspectiveCamera, PdfAndImportanceNormalisation) {
  const PerspectiveCamera c = make_perspective_camera(Vec3(0, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1), 50.f, 8, 6);
  const float cos_max = 0.7f;  // a cone containing the whole frustum (corner ~cos 0.86)
  const Frame f(c.forward);
  Pcg32 rng(3, 4);
  const int n = 2000000;
  double pdf_sum = 0, we_sum = 0;
  for (int i = 0; i < n; ++i) {
    const Vec3 d = f.to_world(square_to_uniform_cone({rng.next_float(), rng.next_float()}, cos_max));
    const double inv_pdf = 1.0 / uniform_cone_pdf(cos_max);
    float rx, ry;
    if (!c.raster_from_direction(d, &rx, &ry)) continue;
    pdf_sum += c.pdf_direction(d) * inv_pdf;
    if (int(rx) == 3 && int(ry) == 2) we_sum += c.importance(d) * dot(d, c.forward) * inv_pdf;
  }
  EXPECT_NEAR(pdf_sum / n, 1.0, 0.01);
  // Integral of We cos over one pixel's solid angle = 1 (a pixel measures mean radiance).
  EXPECT_NEAR(we_sum / n, 1.0, 0.03);
}

TEST(PerspectiveCamera, ConnectionMatchesImportance) {
  const PerspectiveCamera c = make_perspective_camera(Vec3(0, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1), 45.f, 64, 64);
  const Vec3 p(0.3f, 4.f, -0.2f);
  CameraProjection pr;
  ASSERT_TRUE(c.connect(p, Point2{0.3f, 0.7f}, &pr));  // a pinhole ignores the lens sample
  const Vec3 d = normalize(p);
  EXPECT_NEAR(pr.dist, length(p), 1e-5f);
  EXPECT_NEAR(pr.wi.x, -d.x, 1e-6f);
  // factor = We cos_cam / dist^2
  EXPECT_NEAR(pr.factor, c.importance(d) * dot(d, c.forward) / (pr.dist * pr.dist), 1e-3f * pr.factor);
  float rx, ry;
  ASSERT_TRUE(c.raster_from_direction(d, &rx, &ry));
  EXPECT_EQ(pr.rx, rx);
  EXPECT_EQ(pr.ry, ry);
}

}  // namespace
}  // namespace pathspace
