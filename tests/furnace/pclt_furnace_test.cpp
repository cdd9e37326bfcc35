// Furnace tests for pixel cache light tracing (PCLT sec. 3-5): closed scenes with known radiance
// whose walls are Lambertian + mirror, so every part of PCLT carries light: projection (ED), the
// pixel cache (ES+D, gathered) and, in the emissive box, emission through mirror bounces (ES+L).
// Pixels of one iteration share its light paths, so the sample is each iteration's image mean
// (iterations are independent): a one-sample t-test against the closed form, alpha = 0.01
// Sidak-corrected over this file.
//  - Inside of a sphere (radius R, albedo a_d + mirror a_s), point light at the centre. The mirror
//    images the centre onto itself, so the diffuse walls receive I / (R^2 (1 - a_s)) directly, and
//    L = a_d I / (pi R^2 (1 - a_s) (1 - a_s - a_d)) everywhere. The irradiance is constant and the
//    sphere cap within distance r has area pi r^2 exactly, so gathering is unbiased at any radius.
//  - Closed box, walls emitting Le with albedo a_d + mirror a_s: L = Le / (1 - a_d - a_s). Near
//    edges the gather ball reaches the adjacent wall: records within r of an edge (2r/side of a wall)
//    overestimate by up to 25% of their gathered part (sppm_furnace_test), ~0.5% of L at r = 0.04.
//  - The stochastic hash map (count-reweighted, Hachisuka & Jensen 2010) and the stochastic store
//    of a too-small cache (reweighted by candidates / capacity) are unbiased: same sphere test.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>

#include "pathspace/accel/accel.h"
#include "pathspace/integrators/pclt/pclt_integrator.h"
#include "pathspace/scene/scene.h"
#include "support/statistics.h"

namespace pathspace {
namespace {

constexpr int kTestsInFile = 4;
const double kAlpha = testing::sidak(0.01, kTestsInFile);
constexpr int kResolution = 16;

Material diffuse_mirror(float a_d, float a_s) {
  Material m = make_diffuse(Rgb(a_d));
  m.specular = Rgb(a_s);
  return m;
}

void inside_camera(Scene& s) {
  s.camera = make_perspective_camera(Vec3(0.1f, -0.2f, 0.05f), Vec3(0.3f, 1.f, 0.2f), Vec3(0, 0, 1), 90.f, kResolution, kResolution);
  s.ray_epsilon = 1e-4f;
  s.max_path_segments = 1 << 20;  // effectively unlimited: Russian roulette ends paths
}

Scene mirror_sphere_with_point_light(float radius, float a_d, float a_s, float intensity) {
  Scene s;
  s.add_sphere(Vec3(0, 0, 0), radius, s.add_material(diffuse_mirror(a_d, a_s)), Rgb(), /*inward_normals=*/true);
  s.add_point_light(Vec3(0, 0, 0), Rgb(intensity));
  inside_camera(s);
  s.finalize();
  return s;
}

Scene emissive_mirror_box(float le, float a_d, float a_s) {
  Scene s;
  const uint32_t m = s.add_material(diffuse_mirror(a_d, a_s));
  for (int axis = 0; axis < 3; ++axis)
    for (int side = -1; side <= 1; side += 2) {
      const int u = (axis + 1) % 3, v = (axis + 2) % 3;
      Vec3 c[4];
      const float us[4] = {-1, 1, 1, -1}, vs[4] = {-1, -1, 1, 1};
      for (int k = 0; k < 4; ++k) {
        c[k][axis] = float(side);
        c[k][u] = us[k];
        c[k][v] = vs[k];
      }
      Vec3 inward;
      inward[axis] = float(-side);
      if (dot(cross(c[1] - c[0], c[2] - c[0]), inward) < 0.f) std::swap(c[1], c[3]);
      s.add_quad(c[0], c[1], c[2], c[3], m, Rgb(le));
    }
  inside_camera(s);
  s.finalize();
  return s;
}

// Renders `iterations` PCLT iterations, each into its own film, and t-tests their image means.
void expect_iteration_means(const Scene& scene, const PcltSettings& pclt, int iterations, uint64_t seed, double expected) {
  const Accel accel(scene);
  const char* env = std::getenv("PATHSPACE_TEST_SEED");  // rerun with other seeds to check robustness
  PcltIntegrator integrator(scene, accel, pclt, seed + (env ? std::strtoull(env, nullptr, 10) * 1000 : 0));
  double sum = 0, sum_sq = 0;
  size_t records = 0;
  for (int i = 0; i < iterations; ++i) {
    Film film(scene.camera.width, scene.camera.height);
    PathCounters counters;
    integrator.render_pass(uint32_t(i), film, counters);
    ASSERT_EQ(counters.dropped, 0u);
    records += integrator.record_count();
    double m = 0;
    for (const Rgb& p : film.mean().pixels) m += p.r;
    m /= double(film.pixel_count());
    sum += m;
    sum_sq += m * m;
  }
  EXPECT_GT(records, size_t(iterations)) << "the pixel cache must take part";
  const testing::MeanTest t = testing::t_test_mean(sum, sum_sq, iterations, expected);
  EXPECT_GT(t.p, kAlpha) << "mean " << t.mean << " +- " << t.std_error << " (expected " << expected << ", t = " << t.t << ")";
  EXPECT_LT(t.std_error, 0.01 * expected);  // the power to see a 3% bias
  Statistics details;
  integrator.statistics(details);
  std::printf("mean %.5f +- %.5f expected %.5f t %.2f\n%s", t.mean, t.std_error, expected, t.t, format_statistics(details).c_str());
}

double sphere_expected(float radius, float a_d, float a_s, float intensity) {
  return a_d * intensity / (kPi * radius * radius * (1.0 - a_s) * (1.0 - a_s - a_d));
}

TEST(PcltFurnace, MirrorSphereWithPointLight) {
  const float radius = 1.5f, a_d = 0.4f, a_s = 0.3f, intensity = 3.f;
  PcltSettings s;
  s.light_paths = 4000;
  s.initial_radius = 0.3f;  // any radius is unbiased here; a large one keeps the noise low
  expect_iteration_means(mirror_sphere_with_point_light(radius, a_d, a_s, intensity), s, 200, 1,
                         sphere_expected(radius, a_d, a_s, intensity));
}

TEST(PcltFurnace, EmissiveMirrorBox) {
  const float le = 1.f, a_d = 0.4f, a_s = 0.3f;
  PcltSettings s;
  s.light_paths = 16000;
  s.initial_radius = 0.04f;  // edge bias ~0.5% of L (file comment), below the test's resolution
  expect_iteration_means(emissive_mirror_box(le, a_d, a_s), s, 100, 2, le / (1.0 - a_d - a_s));
}

TEST(PcltFurnace, StochasticHashMapIsUnbiased) {
  const float radius = 1.5f, a_d = 0.4f, a_s = 0.3f, intensity = 3.f;
  PcltSettings s;
  s.light_paths = 4000;
  s.initial_radius = 0.3f;
  s.hash_map = PcltHashMap::stochastic;
  s.stochastic_slots = 16;  // few slots: many records compete and are reweighted by the count
  expect_iteration_means(mirror_sphere_with_point_light(radius, a_d, a_s, intensity), s, 200, 3,
                         sphere_expected(radius, a_d, a_s, intensity));
}

TEST(PcltFurnace, StochasticStoreIsUnbiased) {
  const float radius = 1.5f, a_d = 0.4f, a_s = 0.3f, intensity = 3.f;
  PcltSettings s;
  s.light_paths = 4000;
  s.initial_radius = 0.3f;
  s.cache_capacity = 16;  // ~1/4 of the candidates fit
  s.stochastic_store = true;
  expect_iteration_means(mirror_sphere_with_point_light(radius, a_d, a_s, intensity), s, 200, 4,
                         sphere_expected(radius, a_d, a_s, intensity));
}

}  // namespace
}  // namespace pathspace
