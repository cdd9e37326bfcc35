// Unit tests of the thin-lens camera (camera/perspective_camera.h): radius 0 is exactly the pinhole
// (rays and projections bit for bit), the focus plane is sharp, project() inverts generate_ray for
// the same lens point, and the directional pdf and the connection factor are normalised from a lens
// point (Monte Carlo t-tests, alpha = 0.01 Sidak over the 2 of this file).
#include <gtest/gtest.h>

#include <cstring>

#include "pathspace/camera/perspective_camera.h"
#include "pathspace/integrators/common/camera_sample.h"
#include "pathspace/sampling/rng.h"
#include "support/statistics.h"

namespace pathspace {
namespace {

const double kAlpha = testing::sidak(0.01, 2);

PerspectiveCamera lens_camera(float radius, float focus) {
  PerspectiveCamera c = make_perspective_camera(Vec3(1, 2, 3), Vec3(0.2f, 1, -0.1f), Vec3(0, 0, 1), 60.f, 32, 24);
  EXPECT_TRUE(set_thin_lens(&c, radius, focus));
  return c;
}

bool same_bits(const Vec3& a, const Vec3& b) { return std::memcmp(&a, &b, sizeof(Vec3)) == 0; }

// The projection as the pinhole code computed it before the thin lens (lt_kernel.h's project).
bool old_pinhole_project(const PerspectiveCamera& cam, const Vec3& p, CameraProjection* out) {
  const Vec3 to_cam = cam.position - p;
  const float d2 = length_squared(to_cam);
  if (!(d2 > 0.f)) return false;
  const float d = sqrtf(d2);
  const Vec3 dir = -to_cam / d;
  const float c = dot(dir, cam.forward);
  if (c <= 0.f) return false;
  const float sx = dot(dir, cam.right) / c, sy = dot(dir, cam.up) / c;
  out->rx = (sx / cam.tan_x + 1.f) * 0.5f * float(cam.width);
  out->ry = (1.f - sy / cam.tan_y) * 0.5f * float(cam.height);
  out->wi = to_cam / d;
  out->dist = d;
  out->factor = 1.f / (cam.pixel_area() * c * c * c * d2);
  return true;
}

TEST(ThinLens, ZeroRadiusIsThePinholeBitForBit) {
  PerspectiveCamera c = lens_camera(0.f, 7.f);
  ASSERT_TRUE(c.is_pinhole());
  Pcg32 rng(5, 6);
  for (int i = 0; i < 20000; ++i) {
    const float rx = rng.next_float() * 32.f, ry = rng.next_float() * 24.f;
    const Point2 u{rng.next_float(), rng.next_float()};
    const Ray a = c.generate_ray(rx, ry, u), b = c.generate_ray(rx, ry);
    ASSERT_TRUE(same_bits(a.o, b.o) && same_bits(a.d, b.d)) << i;
    const Vec3 p = c.position + b.d * (0.5f + 20.f * rng.next_float()) + Vec3(rng.next_float() - 0.5f, 0.f, 0.f);
    CameraProjection n, o;
    ASSERT_EQ(c.project(p, u, &n), old_pinhole_project(c, p, &o));
    ASSERT_EQ(n.rx, o.rx);
    ASSERT_EQ(n.ry, o.ry);
    ASSERT_EQ(n.dist, o.dist);
    ASSERT_EQ(n.factor, o.factor);
    ASSERT_TRUE(same_bits(n.wi, o.wi));
  }
  // A pinhole reads no lens dimension: the sampled camera ray is the chief ray of the jittered raster position.
  const Sampler s(1, 77, 3);
  const Ray r = sample_camera_ray(c, s, 77, 0.f);
  const Ray chief = c.generate_ray(float(77 % 32) + s.at(dims::kPixelX), float(77 / 32) + s.at(dims::kPixelY));
  EXPECT_TRUE(same_bits(r.o, chief.o) && same_bits(r.d, chief.d));
  // Invalid lens parameters leave the camera alone.
  EXPECT_FALSE(set_thin_lens(&c, -1.f, 5.f));
  EXPECT_FALSE(set_thin_lens(&c, 0.1f, 0.f));
  EXPECT_FALSE(set_thin_lens(&c, 0.1f, kInfinity));
  EXPECT_TRUE(c.is_pinhole());
}

// Every ray of one raster position meets the focus plane in the same point, and every lens point
// sees a point of the focus plane at the same raster position; off the plane the image moves.
TEST(ThinLens, FocusPlaneIsSharp) {
  const float f = 6.f;
  const PerspectiveCamera c = lens_camera(0.4f, f);
  Pcg32 rng(7, 8);
  float max_offplane = 0.f;
  for (int i = 0; i < 2000; ++i) {
    const float rx = rng.next_float() * 32.f, ry = rng.next_float() * 24.f;
    const Vec3 focus_point = c.position + c.direction(rx, ry) * (f / dot(c.direction(rx, ry), c.forward));
    for (int k = 0; k < 4; ++k) {
      const Point2 u{rng.next_float(), rng.next_float()};
      const Ray ray = c.generate_ray(rx, ry, u);
      EXPECT_LE(length(ray.o - c.position), 0.4f * (1.f + 1e-5f));
      EXPECT_NEAR(dot(ray.o - c.position, c.forward), 0.f, 1e-5f);  // on the lens plane
      const float t = f / dot(ray.d, c.forward);
      EXPECT_LT(length(ray.o + ray.d * t - focus_point), 2e-5f * f) << i;
      CameraProjection pr;
      ASSERT_TRUE(c.project(focus_point, u, &pr));
      EXPECT_NEAR(pr.rx, rx, 2e-3f);
      EXPECT_NEAR(pr.ry, ry, 2e-3f);
      CameraProjection off;
      ASSERT_TRUE(c.project(c.position + (focus_point - c.position) * 0.5f, u, &off));
      max_offplane = fmaxf(max_offplane, fabsf(off.rx - rx) + fabsf(off.ry - ry));
    }
  }
  EXPECT_GT(max_offplane, 1.f);  // a point at half the focus distance is blurred over pixels
}

// project() inverts generate_ray: a point on the ray of (raster, lens sample) projects back to that
// raster position through the same lens point, with wi pointing back along the ray to its origin.
TEST(ThinLens, ProjectRoundTripsGenerateRay) {
  const PerspectiveCamera c = lens_camera(0.25f, 3.f);
  Pcg32 rng(9, 10);
  for (int i = 0; i < 20000; ++i) {
    const float rx = rng.next_float() * 32.f, ry = rng.next_float() * 24.f;
    const Point2 u{rng.next_float(), rng.next_float()};
    const Ray ray = c.generate_ray(rx, ry, u);
    const float t = 0.2f + 15.f * rng.next_float();
    CameraProjection pr;
    ASSERT_TRUE(c.project(ray.o + ray.d * t, u, &pr));
    EXPECT_NEAR(pr.rx, rx, 3e-3f) << i;
    EXPECT_NEAR(pr.ry, ry, 3e-3f) << i;
    EXPECT_NEAR(pr.dist, t, 1e-5f * (1.f + t));
    EXPECT_GT(dot(pr.wi, -ray.d), 1.f - 1e-5f);
    CameraProjection clipped;
    EXPECT_TRUE(c.connect(ray.o + ray.d * t, u, &clipped));
  }
  CameraProjection pr;
  EXPECT_FALSE(c.project(c.position - c.forward, Point2{0.5f, 0.5f}, &pr));  // behind the lens
}

// From a fixed lens point, generate_ray with a uniform raster position has the solid-angle density
// pdf_direction: E[1_cone(d) / pdf(d)] = the cone's solid angle 2 pi (1 - cos_max).
TEST(ThinLens, DirectionPdfFromALensPoint) {
  const PerspectiveCamera c = lens_camera(0.5f, 2.f);
  const Point2 u{0.9f, 0.2f};  // an off-centre lens point
  const Vec3 o = c.generate_ray(16.f, 12.f, u).o;
  const float cos_max = 0.95f;  // inside the frustum seen from that lens point
  Pcg32 rng(11, 12);
  const int n = 400000;
  double sum = 0, sum_sq = 0;
  for (int i = 0; i < n; ++i) {
    const Ray ray = c.generate_ray(rng.next_float() * 32.f, rng.next_float() * 24.f, u);
    ASSERT_TRUE(same_bits(ray.o, o));
    const double x = dot(ray.d, c.forward) > cos_max ? 1.0 / c.pdf_direction(ray.d) : 0.0;
    sum += x;
    sum_sq += x * x;
  }
  const testing::MeanTest t = testing::t_test_mean(sum, sum_sq, n, 2.0 * kPi * (1.0 - cos_max));
  EXPECT_GE(t.p, kAlpha) << "mean " << t.mean << " +- " << t.std_error << ", t " << t.t;
}

// The connection factor is We cos / (d^2 p_lens): splatting a surface of unit radiance that fills
// the view gives every pixel the value 1, in and out of focus and for every lens point. Points are
// uniform on a plane (tilted, behind the focus plane) and each adds factor * cos_surface * area to
// the pixel it lands in (LT's splat of a uniform emitter), so the sum over the image is W * H.
TEST(ThinLens, ConnectionFactorSplatsUnitRadiance) {
  const PerspectiveCamera c = lens_camera(0.3f, 2.f);
  const Vec3 centre = c.position + c.forward * 5.f;
  const Vec3 n = normalize(-c.forward + c.right * 0.3f);
  const Vec3 a = normalize(cross(n, c.up)), b = cross(n, a);
  const float half = 6.f;  // the square [-half, half]^2 covers the whole view from every lens point
  const double area = 4.0 * double(half) * double(half);
  Pcg32 rng(13, 14);
  const int n_samples = 1000000;
  double sum = 0, sum_sq = 0;
  for (int i = 0; i < n_samples; ++i) {
    const Vec3 p = centre + a * ((2.f * rng.next_float() - 1.f) * half) + b * ((2.f * rng.next_float() - 1.f) * half);
    const Point2 u{rng.next_float(), rng.next_float()};
    CameraProjection pr;
    double x = 0;
    if (c.connect(p, u, &pr)) x = double(pr.factor) * fabs(dot(pr.wi, n)) * area;
    sum += x;
    sum_sq += x * x;
  }
  const testing::MeanTest t = testing::t_test_mean(sum, sum_sq, n_samples, double(c.width) * double(c.height));
  EXPECT_GE(t.p, kAlpha) << "mean " << t.mean << " +- " << t.std_error << ", t " << t.t;
}

}  // namespace
}  // namespace pathspace
