// Chi-square tests of next-event estimation (scene/light_sampling.h): the directions produced by
// sample_light against light_pdf, which must agree, for a sphere seen from outside (cone
// sampling), a sphere seen from inside (area sampling) and triangles (area sampling converted to
// solid angle; and by an emission map's cells, lights/emission_cells.h). Every sample's pdf_w must
// also equal light_pdf at the sampled point (for cells: all but points a rounding step from a cell
// edge, which may take the neighbour's density; at most 1 in 10^4).
// Significance: alpha = 0.01 for the file, Sidak-corrected over its kChi2Tests chi-square tests.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <vector>

#include "pathspace/scene/emission_cells_build.h"
#include "pathspace/scene/light_sampling.h"
#include "pathspace/scene/texture.h"
#include "support/chi2.h"
#include "support/statistics.h"

namespace pathspace {
namespace {

constexpr int kChi2Tests = 6;
const double kAlpha = testing::sidak(0.01, kChi2Tests);

// A scene of one emitter: a triangle or a sphere.
struct OneLight {
  std::vector<Vec3> positions;
  std::vector<Triangle> triangles;
  std::vector<Sphere> spheres;
  std::vector<Point2> uvs;
  std::vector<ImageTexture> textures;
  std::vector<TextureView> texture_views;
  std::vector<float> emission_cells;
  Light light;
  SceneView view() const {
    SceneView v;
    v.positions = positions.data();
    v.uvs = uvs.empty() ? nullptr : uvs.data();
    v.textures = texture_views.data();
    v.num_textures = uint32_t(texture_views.size());
    v.emission_cells = emission_cells.data();
    v.num_emission_cells = uint32_t(emission_cells.size());
    v.triangles = triangles.data();
    v.num_triangles = uint32_t(triangles.size());
    v.spheres = spheres.data();
    v.num_spheres = uint32_t(spheres.size());
    v.lights = &light;
    v.num_lights = 1;
    return v;
  }
};

OneLight triangle_light(const Vec3& p0, const Vec3& p1, const Vec3& p2) {
  OneLight s;
  s.positions = {p0, p1, p2};
  s.triangles = {Triangle{{0, 1, 2}, 0, 0}};
  s.light.type = LightType::area_triangle;
  s.light.value = Rgb(1.f);
  s.light.two_sided = true;
  return s;
}

// The triangle with an emission map of a bright corner and a dark stripe, sampled by its cells.
OneLight mapped_triangle_light(const Vec3& p0, const Vec3& p1, const Vec3& p2) {
  OneLight s = triangle_light(p0, p1, p2);
  ImageTexture map;
  map.name = "chi2 map";
  map.width = map.height = 24;
  for (int y = 0; y < 24; ++y)
    for (int x = 0; x < 24; ++x)
      map.texels.push_back(x < 5 && y < 5 ? Rgb(20.f) : y == 12 ? Rgb(0.f) : Rgb(0.3f + 0.05f * float(x), 0.5f, 0.4f));
  s.textures.push_back(std::move(map));
  s.texture_views = {s.textures[0].view()};
  s.uvs = {{0.f, 0.f}, {1.f, 0.f}, {0.f, 1.f}};
  s.light.texture = 0;
  std::vector<Light> lights{s.light};
  s.emission_cells = build_emission_cells(s.triangles, s.uvs, s.textures, &lights);
  s.light = lights[0];
  return s;
}

OneLight sphere_light(const Vec3& center, float radius, bool inward) {
  OneLight s;
  s.spheres = {Sphere{center, radius, 0, 0, inward}};
  s.light.type = LightType::area_sphere;
  s.light.value = Rgb(1.f);
  return s;
}

// Möller–Trumbore, for the pdf of a direction (the test needs its own hit point and normal).
bool hit_triangle(const Vec3& o, const Vec3& d, const Vec3& p0, const Vec3& p1, const Vec3& p2, float* t) {
  const Vec3 e1 = p1 - p0, e2 = p2 - p0, pv = cross(d, e2);
  const float det = dot(e1, pv);
  if (fabsf(det) < 1e-12f) return false;
  const Vec3 tv = o - p0, qv = cross(tv, e1);
  const float u = dot(tv, pv) / det, v = dot(d, qv) / det;
  *t = dot(e2, qv) / det;
  return u >= 0.f && v >= 0.f && u + v <= 1.f && *t > 0.f;
}

// Solid-angle density of sample_light towards w: light_pdf at the first point of the light along w.
double direction_pdf(const OneLight& s, const SceneView& v, const Vec3& ref, const Vec3& w) {
  float t;
  if (s.light.type == LightType::area_triangle) {
    const Vec3 p0 = s.positions[0], p1 = s.positions[1], p2 = s.positions[2];
    if (!hit_triangle(ref, w, p0, p1, p2, &t)) return 0.0;
    return light_pdf(v, s.light, ref, ref + w * t, triangle_normal(p0, p1, p2), 0.f);
  }
  const Sphere& sp = s.spheres[0];
  if (!intersect_sphere(sp, ref, w, 0.f, kInfinity, &t)) return 0.0;
  const Vec3 p = ref + w * t;
  return light_pdf(v, s.light, ref, p, sphere_normal(sp, p), 0.f);
}

void check_light(const char* name, const OneLight& s, const Vec3& ref, const Vec3& axis, uint64_t seed) {
  SCOPED_TRACE(name);
  const SceneView v = s.view();
  uint64_t bad = 0, off_edge = 0;
  std::string first;
  testing::Chi2Options o;
  o.name = name;
  o.seed = seed;
  o.alpha = kAlpha;
  const auto r = testing::direction_chi2(
      {axis},
      [&](Pcg32& rng) {
        LightSample ls;
        if (!sample_light(v, s.light, ref, 0.f, {rng.next_float(), rng.next_float()}, &ls)) return testing::Outcome{};
        // The sample's own pdf must be light_pdf at the sampled point, and wi must point at it.
        const Vec3 n = s.light.type == LightType::area_triangle
                           ? triangle_normal(s.positions[0], s.positions[1], s.positions[2])
                           : sphere_normal(s.spheres[0], ls.p);
        const float pdf = light_pdf(v, s.light, ref, ls.p, n, 0.f);
        const float dir_err = length(normalize(ls.p - ref) - ls.wi);
        if (!(fabsf(pdf - ls.pdf_w) <= 1e-3f * pdf) || dir_err > 1e-4f || ls.delta) {
          if (s.light.emission_grid > 0 && dir_err <= 1e-4f && !ls.delta && ++off_edge <= o.samples / 10000) return testing::Outcome{0, 0, 0, ls.wi};
          if (bad++ == 0)
            first = "pdf_w " + std::to_string(ls.pdf_w) + " light_pdf " + std::to_string(pdf) + " direction error " +
                    std::to_string(dir_err);
        }
        return testing::Outcome{0, 0, 0, ls.wi};
      },
      [&](const Vec3& w) { return direction_pdf(s, v, ref, w); }, o);
  std::printf("%s: chi2 %.1f dof %.0f p %.4f\n", name, r.statistic, r.dof, r.p_value);
  EXPECT_TRUE(r.passed(kAlpha)) << "chi2 " << r.statistic << " dof " << r.dof << " p " << r.p_value << " < " << kAlpha
                                << " " << r.error << "; evidence: " << r.evidence;
  EXPECT_EQ(bad, 0u) << first;
}

TEST(LightChi2, SphereFromOutside) {  // 2 tests: a small distant sphere and a large near one
  const Vec3 ref(0.3f, -0.2f, 0.1f);
  const OneLight far = sphere_light(Vec3(1.f, 2.f, 6.f), 0.5f, false);
  check_light("light_sphere_far", far, ref, far.spheres[0].center - ref, 1);
  const OneLight near = sphere_light(Vec3(0.f, 1.5f, 0.f), 1.2f, false);
  check_light("light_sphere_near", near, ref, near.spheres[0].center - ref, 2);
}

TEST(LightChi2, SphereFromInside) {  // 1 test; inward normals so the wall emits towards ref
  const OneLight s = sphere_light(Vec3(0.f, 0.f, 0.f), 2.f, true);
  check_light("light_sphere_inside", s, Vec3(0.5f, -0.8f, 0.3f), Vec3(0.f, 0.f, 1.f), 3);
}

TEST(LightChi2, Triangle) {  // 2 tests: seen head-on and at a grazing angle
  const Vec3 ref(0.2f, 0.1f, 0.f);
  const OneLight head_on = triangle_light(Vec3(-1.f, -1.f, 2.f), Vec3(1.5f, -0.5f, 2.f), Vec3(0.f, 1.f, 2.5f));
  check_light("light_triangle", head_on, ref, Vec3(0.f, 0.f, 1.f), 4);
  const OneLight grazing = triangle_light(Vec3(2.f, -1.f, 0.1f), Vec3(4.f, -1.f, 0.4f), Vec3(3.f, 1.5f, 0.2f));
  check_light("light_triangle_grazing", grazing, ref, Vec3(1.f, 0.f, 0.1f), 5);
}

TEST(LightChi2, TriangleWithEmissionMapCells) {  // 1 test
  const OneLight mapped = mapped_triangle_light(Vec3(-1.f, -1.f, 2.f), Vec3(1.5f, -0.5f, 2.f), Vec3(0.f, 1.f, 2.5f));
  ASSERT_GT(mapped.light.emission_grid, 4u);
  check_light("light_triangle_cells", mapped, Vec3(0.2f, 0.1f, 0.f), Vec3(0.f, 0.f, 1.f), 6);
}

}  // namespace
}  // namespace pathspace
