#include "support/integrator_comparison.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "pathspace/io/image_io.h"
#include "pathspace/materials/bsdf.h"
#include "support/statistics.h"

namespace pathspace::testing {

Rendered render_integrator(const Scene& scene, const Accel& accel, const RenderConfig& config, uint32_t passes,
                           std::vector<NamedImage>* aovs) {
  RenderSnapshot snap = render(scene, accel, config, RunLimit::for_passes(passes));
  EXPECT_EQ(snap.stats.dropped_samples, 0u) << config.integrator;
  if (aovs) *aovs = std::move(snap.aovs);
  return {std::move(snap.mean), std::move(snap.variance)};
}

Rendered render_integrator(const Scene& scene, const RenderConfig& config, uint32_t passes, std::vector<NamedImage>* aovs) {
  const Accel accel(scene);
  return render_integrator(scene, accel, config, passes, aovs);
}

void apply_mask(Rendered* r, const std::vector<bool>& mask) {
  for (size_t i = 0; i < mask.size(); ++i)
    if (mask[i]) r->mean.pixels[i] = r->variance.pixels[i] = Rgb();
}

void expect_same_image(const Rendered& a, const Rendered& b, const std::string& what, double alpha_image,
                       const std::string& name_a, const std::string& name_b) {
  const ImageZTest z = image_z_test(a.mean, a.variance, b.mean, b.variance, 1e-3, alpha_image);
  std::printf("%s: %zu of %zu pixels fail (allowed %zu); image means %.5f vs %.5f (z = %.2f)\n", what.c_str(), z.failed,
              z.pixels, z.allowed, z.mean_a, z.mean_b, z.mean_z);
  if (z.passed()) return;
  const std::string dir = evidence_dir();
  std::string worst;
  int listed = 0;
  for (size_t i = 0; i < a.mean.size() && listed < 12; ++i) {
    const double d = average(a.mean.pixels[i]) - average(b.mean.pixels[i]);
    const double sd = std::sqrt(average(a.variance.pixels[i]) + average(b.variance.pixels[i]) + 1e-8);
    if (std::fabs(d / sd) > 3.29 && listed++ < 12)
      worst += fmt::format("\n  pixel ({}, {}): {:.5f} vs {:.5f} (z {:.1f})", i % size_t(a.mean.width), i / size_t(a.mean.width),
                           average(a.mean.pixels[i]), average(b.mean.pixels[i]), d / sd);
  }
  ADD_FAILURE() << what << ": " << z.failed << " of " << z.pixels << " pixels differ (at most " << z.allowed
                << " allowed); image means " << z.mean_a << " vs " << z.mean_b << " (z = " << z.mean_z << "); images in "
                << dir << worst;
  write_image(dir + "/" + what + "-" + name_a + ".exr", a.mean);
  write_image(dir + "/" + what + "-" + name_b + ".exr", b.mean);
}

namespace {
// Lens samples the probe rays go through: the centre for a pinhole; for a thin lens the centre and
// 8 points near the rim (concentric map of a 3x3 grid reaching 0.96 of the radius), since a pixel
// integrates over the whole lens.
std::vector<Point2> lens_probes(const PerspectiveCamera& c) {
  if (c.is_pinhole()) return {Point2{0.5f, 0.5f}};
  std::vector<Point2> u;
  for (int k = 0; k < 9; ++k) u.push_back(Point2{0.02f + 0.48f * float(k % 3), 0.02f + 0.48f * float(k / 3)});
  return u;
}
}  // namespace

Image footprint_average(const Scene& scene, const Accel& accel, int n, const std::function<Rgb(const SurfaceHit*)>& radiance) {
  const PerspectiveCamera& camera = scene.camera;
  Image img(camera.width, camera.height);
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      Rgb sum;
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
          SurfaceHit hit;
          const Ray ray = camera.generate_ray(float(x) + (float(i) + 0.5f) / float(n), float(y) + (float(j) + 0.5f) / float(n));
          sum += radiance(accel.intersect(ray, &hit) ? &hit : nullptr);
        }
      img.at(x, y) = sum * (1.f / float(n * n));
    }
  return img;
}

void expect_matches_exact(const Rendered& r, const Image& expected, const std::string& what, double alpha_image, bool whole_image) {
  const Image zero(expected.width, expected.height);
  const ImageZTest z = image_z_test(r.mean, r.variance, expected, zero, 1e-3, alpha_image);
  EXPECT_TRUE(whole_image ? z.passed() : z.failed <= z.allowed)
      << what << ": " << z.failed << " of " << z.pixels << " pixels failed (allowed " << z.allowed << "), mean " << z.mean_a
      << " vs " << z.mean_b << ", p " << z.mean_p;
}

std::vector<bool> specular_first_hit_mask(const Scene& scene, const Accel& accel) {
  const SceneView v = scene.view();
  const std::vector<Point2> lens = lens_probes(v.camera);
  std::vector<bool> mask(size_t(v.camera.width) * size_t(v.camera.height), false);
  for (int j = 0; j < v.camera.height; ++j)
    for (int i = 0; i < v.camera.width; ++i)
      for (int k = 0; k < 9; ++k)
        for (const Point2& u : lens) {
          SurfaceHit hit;
          const Ray ray = v.camera.generate_ray(float(i) + (0.05f + 0.45f * float(k % 3)), float(j) + (0.05f + 0.45f * float(k / 3)), u);
          if (accel.intersect(ray, &hit) && !bsdf_has_non_delta(v.materials[hit.material]))
            mask[size_t(i) + size_t(j) * size_t(v.camera.width)] = true;
        }
  return mask;
}

std::vector<bool> smooth_pixels(const Scene& scene, const Accel& accel, float reach, bool exclude_ceiling, bool exclude_glossy) {
  const SceneView view = scene.view();
  const int w = scene.camera.width, h = scene.camera.height;
  const std::vector<Point2> lens = lens_probes(view.camera);
  const int probes = 16 * int(lens.size());
  std::vector<bool> keep(size_t(w) * size_t(h), true);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      bool ok = true;
      Vec3 n0;
      uint32_t m0 = 0;
      for (int k = 0; k < probes && ok; ++k) {
        SurfaceHit hit;
        const int r = k % 16;
        const Ray ray = view.camera.generate_ray(float(x) + (float(r % 4) + 0.5f) / 4.f, float(y) + (float(r / 4) + 0.5f) / 4.f,
                                                 lens[size_t(k / 16)]);
        if (!accel.intersect(ray, &hit)) {
          ok = false;
          break;
        }
        const Material& m = view.materials[hit.material];
        if (k == 0) {
          n0 = hit.ng;
          m0 = hit.material;
        }
        ok = hit.material == m0 && dot(hit.ng, n0) > 0.999f && hit.light == kNoLight && bsdf_has_non_delta(m) &&
             is_black(m.specular) && !(exclude_glossy && !is_black(m.glossy));
        const Frame f(hit.ng);
        for (int d = 0; d < 8 && ok; ++d) {
          const float a = float(d) * kPi / 4.f;
          const Vec3 dir = f.s * cosf(a) + f.t * sinf(a);
          SurfaceHit probe;
          ok = !accel.intersect(Ray{hit.p + hit.ng * 1e-3f, dir, 0.f, reach}, &probe);
        }
      }
      if (exclude_ceiling && n0.z < -0.5f) ok = false;
      keep[size_t(y) * size_t(w) + size_t(x)] = ok;
    }
  return keep;
}

Image compact_pixels(const Image& img, const std::vector<bool>& keep) {
  Image out;
  out.width = int(std::count(keep.begin(), keep.end(), true));
  out.height = 1;
  for (size_t i = 0; i < keep.size(); ++i)
    if (keep[i]) out.pixels.push_back(img.pixels[i]);
  return out;
}

uint64_t test_seed_base() {
  const char* env = std::getenv("PATHSPACE_TEST_SEED");
  return env ? std::strtoull(env, nullptr, 10) * 16 : 0;
}

uint64_t test_seed(uint64_t seed) { return test_seed_base() + seed; }

}  // namespace pathspace::testing
