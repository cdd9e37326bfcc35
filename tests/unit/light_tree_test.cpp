// The light tree (scene/light_tree.h, lights/light_tree_view.h): sample() and probability() agree to
// the bit, the probabilities at a point sum to one, sample() picks each light with exactly its
// probability (a fine grid of u partitions [0, 1) into intervals of those lengths), the importance
// is conservative (every light that can light a point has a non-zero probability there), and the
// tree over 30,000 emitters stays shallow.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <random>

#include "pathspace/scene/builtin_scenes.h"
#include "pathspace/scene/light_selection.h"
#include "pathspace/scene/light_tree.h"
#include "pathspace/scene/scene.h"

namespace pathspace {
namespace {

// Area triangles facing random ways, two-sided ones, emissive spheres, point and spot lights, a
// directional light and an environment: every kind of light bounds, and infinite lights.
Scene many_lights(uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(-1.f, 1.f);
  Scene s;
  s.camera.width = s.camera.height = 4;
  const uint32_t m = s.add_material(Material{});
  auto point = [&] { return Vec3(u(rng), u(rng), u(rng)) * 4.f; };
  for (int i = 0; i < 40; ++i) {
    const Vec3 c = point();
    s.add_triangle(c, c + Vec3(u(rng), u(rng), u(rng)) * 0.3f, c + Vec3(u(rng), u(rng), u(rng)) * 0.3f, m,
                   Rgb(1.f + float(i % 5), 1.f, 0.5f), i % 7 == 0);
  }
  for (int i = 0; i < 5; ++i) s.add_sphere(point(), 0.2f, m, Rgb(2.f, 2.f, 2.f));
  for (int i = 0; i < 5; ++i) s.add_point_light(point(), Rgb(3.f, 1.f, 1.f));
  for (int i = 0; i < 5; ++i) {
    const Vec3 p = point();
    s.add_spot_light(p, -p, Rgb(5.f), std::cos(0.6f), std::cos(0.3f));
  }
  s.add_directional_light(Vec3(0.f, -1.f, 0.2f), Rgb(1.f));
  s.add_environment_light(Rgb(0.1f));
  s.light_selection = LightSelection::bvh;
  s.finalize();
  return s;
}

struct Shading {
  Vec3 p, n;
};

std::vector<Shading> shading_points(uint32_t seed, int count) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(-1.f, 1.f);
  std::vector<Shading> out;
  for (int i = 0; i < count; ++i) {
    const Vec3 n = Vec3(u(rng), u(rng), u(rng));
    out.push_back({Vec3(u(rng), u(rng), u(rng)) * 6.f, i % 4 == 0 ? Vec3(0.f) : normalize(n)});
  }
  return out;
}

TEST(LightTree, SampleAndProbabilityAgreeAndSumToOne) {
  const Scene scene = many_lights(1);
  const SceneView view = scene.view();
  ASSERT_TRUE(view.light_tree.active);
  EXPECT_EQ(view.light_tree.num_infinite, 2u);
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> uniform(0.f, 1.f);
  for (const Shading& x : shading_points(2, 200)) {
    double sum = 0.0;
    for (uint32_t i = 0; i < view.num_lights; ++i) sum += light_selection_probability_at(view, x.p, x.n, i);
    // Probability is lost only where no light of a subtree can reach the point: at most the sum.
    EXPECT_LE(sum, 1.0 + 1e-5);
    EXPECT_GT(sum, 0.25);
    for (int k = 0; k < 50; ++k) {
      float prob = -1.f;
      const uint32_t light = select_light_at(view, x.p, x.n, uniform(rng), &prob);
      if (light == LightTreeView::kNone) {
        EXPECT_EQ(prob, 0.f);
        continue;
      }
      EXPECT_GT(prob, 0.f);
      EXPECT_EQ(prob, light_selection_probability_at(view, x.p, x.n, light)) << "light " << light;
    }
  }
}

// Where every light's importance is non-zero (points and spheres emit every way), nothing is lost.
TEST(LightTree, ProbabilitiesSumToOneWhenEveryLightReaches) {
  Scene s;
  s.camera.width = s.camera.height = 4;
  const uint32_t m = s.add_material(Material{});
  for (int i = 0; i < 17; ++i) s.add_point_light(Vec3(float(i), float(i % 3), 0.f), Rgb(1.f + float(i)));
  for (int i = 0; i < 6; ++i) s.add_sphere(Vec3(float(i), 5.f, 1.f), 0.3f, m, Rgb(1.f));
  s.light_selection = LightSelection::bvh;
  s.finalize();
  const SceneView view = s.view();
  for (const Shading& x : shading_points(3, 100)) {
    double sum = 0.0;
    for (uint32_t i = 0; i < view.num_lights; ++i) sum += light_selection_probability_at(view, x.p, x.n, i);
    EXPECT_NEAR(sum, 1.0, 1e-5);
  }
}

// sample() maps u in [0, 1) onto intervals whose lengths are the probabilities: on a grid of 2^20
// values of u, each light's share differs from its probability by the grid's resolution only.
TEST(LightTree, SamplesEachLightWithItsProbability) {
  const Scene scene = many_lights(4);
  const SceneView view = scene.view();
  constexpr uint32_t kGrid = 1u << 20;
  for (const Shading& x : shading_points(5, 6)) {
    std::map<uint32_t, uint32_t> count;
    for (uint32_t k = 0; k < kGrid; ++k) {
      float prob;
      ++count[select_light_at(view, x.p, x.n, (float(k) + 0.5f) / float(kGrid), &prob)];
    }
    double none = 1.0;
    for (uint32_t i = 0; i < view.num_lights; ++i) {
      const double pmf = light_selection_probability_at(view, x.p, x.n, i);
      none -= pmf;
      // Each remapping of u at a node can move an interval's end by a few grid steps.
      EXPECT_NEAR(double(count[i]) / kGrid, pmf, 64.0 / kGrid) << "light " << i;
    }
    EXPECT_NEAR(double(count[LightTreeView::kNone]) / kGrid, none, 64.0 / kGrid);
  }
}

// Conservative importance: a triangle whose front faces a point (some part of it, from the point's
// side) gets a non-zero probability there, as do spot lights whose cone holds the point.
TEST(LightTree, EveryLightThatReachesAPointCanBePicked) {
  const Scene scene = many_lights(6);
  const SceneView view = scene.view();
  int checked = 0;
  for (const Shading& x : shading_points(7, 300)) {
    for (uint32_t i = 0; i < view.num_lights; ++i) {
      const Light& l = view.lights[i];
      bool reaches = false;
      if (l.type == LightType::area_triangle) {
        const Triangle& t = view.triangles[l.shape];
        const Vec3 p0 = view.positions[t.v[0]], p1 = view.positions[t.v[1]], p2 = view.positions[t.v[2]];
        const Vec3 ng = triangle_normal(p0, p1, p2);
        for (int a = 0; a <= 4 && !reaches; ++a)
          for (int b = 0; a + b <= 4 && !reaches; ++b) {
            const Vec3 q = p0 + (p1 - p0) * (float(a) / 4.f) + (p2 - p0) * (float(b) / 4.f);
            const Vec3 d = normalize(x.p - q);
            const float c = dot(ng, d);
            const bool emits = c > 1e-3f || (l.two_sided && c < -1e-3f);
            const bool received = length_squared(x.n) == 0.f || fabsf(dot(x.n, d)) > 1e-3f;
            reaches = emits && received;
          }
      } else if (l.type == LightType::spot) {
        const Vec3 d = normalize(x.p - l.position);
        reaches = spot_falloff(l, d) > 0.f && (length_squared(x.n) == 0.f || fabsf(dot(x.n, d)) > 1e-3f);
      } else {
        reaches = true;
      }
      if (!reaches) continue;
      ++checked;
      EXPECT_GT(light_selection_probability_at(view, x.p, x.n, i), 0.f) << "light " << i << " at point " << x.p.x;
    }
  }
  EXPECT_GT(checked, 5000);
}

// A hard-edged spot (pbrt-v4 conedelta 0, Mitsuba beam_width = cutoff_angle) has no spread beyond
// its cone: its bounds once rejected even the points on its axis, so the tree never picked it and
// the spot rendered black.
TEST(LightTree, HardEdgedSpotIsPickedInsideItsCone) {
  Scene s;
  s.camera.width = s.camera.height = 4;
  const uint32_t m = s.add_material(Material{});
  s.add_quad(Vec3(-1.f, 2.f, -1.f), Vec3(-1.f, 2.f, 1.f), Vec3(1.f, 2.f, 1.f), Vec3(1.f, 2.f, -1.f), m, Rgb(1.f));
  const float cos_cone = std::cos(0.3f);
  s.add_spot_light(Vec3(3.f, 1.f, 0.f), Vec3(0.f, -1.f, 0.f), Rgb(5.f), cos_cone, cos_cone);
  s.light_selection = LightSelection::bvh;
  s.finalize();
  const SceneView view = s.view();
  ASSERT_TRUE(view.light_tree.active);
  const uint32_t spot = uint32_t(s.lights.size() - 1);
  EXPECT_GT(light_selection_probability_at(view, Vec3(3.f, 0.f, 0.f), Vec3(0.f, 1.f, 0.f), spot), 0.f) << "on the axis";
  EXPECT_GT(light_selection_probability_at(view, Vec3(3.2f, 0.f, 0.f), Vec3(0.f), spot), 0.f) << "inside the cone, in a medium";
  EXPECT_EQ(light_selection_probability_at(view, Vec3(5.f, 0.f, 0.f), Vec3(0.f, 1.f, 0.f), spot), 0.f) << "outside the cone";
}

TEST(LightTree, ThirtyThousandEmittersMakeAShallowTree) {
  Scene s;
  s.camera.width = s.camera.height = 4;
  const uint32_t m = s.add_material(Material{});
  for (int i = 0; i < 150; ++i)
    for (int j = 0; j < 100; ++j) {
      const Vec3 p(float(i) * 0.01f, 2.f, float(j) * 0.01f);
      s.add_quad(p, p + Vec3(0.f, 0.f, 0.01f), p + Vec3(0.01f, 0.f, 0.01f), p + Vec3(0.01f, 0.f, 0.f), m, Rgb(1.f));
    }
  s.light_selection = LightSelection::bvh;
  s.finalize();
  ASSERT_EQ(s.lights.size(), 30000u);
  EXPECT_EQ(s.light_tree().nodes().size(), 2u * 30000u - 1u);
  EXPECT_LE(s.light_tree().depth(), 40);
  EXPECT_GE(s.light_tree().depth(), 15);  // log2(30000) ≈ 14.9
}

// The tree stays off where it would pick as power does: the built-in Cornell box's emitter is one
// quad as two triangles of the same bounds, so bvh renders it exactly as power (and uniform) do.
TEST(LightTree, OffWhereItCannotDifferFromPower) {
  Scene cornell = make_builtin_scene("cornell-box", 8, 8);
  cornell.light_selection = LightSelection::bvh;
  cornell.finalize();
  EXPECT_FALSE(cornell.view().light_tree.active);
  Scene sky = make_builtin_scene("cornell-glossy-background", 8, 8);  // an environment light only
  sky.light_selection = LightSelection::bvh;
  sky.finalize();
  EXPECT_FALSE(sky.view().light_tree.active);
  Scene with_point = make_builtin_scene("cornell-box", 8, 8);
  with_point.add_point_light(Vec3(0.f, 0.f, 1.f), Rgb(1.f));
  with_point.light_selection = LightSelection::bvh;
  with_point.finalize();
  EXPECT_TRUE(with_point.view().light_tree.active);
}

TEST(LightTree, MergedConesHoldBothCones) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> u(-1.f, 1.f);
  for (int k = 0; k < 1000; ++k) {
    LightBounds a, b;
    a.phi = b.phi = 1.f;
    a.box.expand(Vec3(0.f));
    b.box.expand(Vec3(1.f));
    a.w = normalize(Vec3(u(rng), u(rng), u(rng)));
    b.w = normalize(Vec3(u(rng), u(rng), u(rng)));
    a.cos_theta_o = u(rng);
    b.cos_theta_o = k % 3 == 0 ? 1.f : u(rng);
    const LightBounds m = merge_light_bounds(a, b);
    const float theta_m = std::acos(std::clamp(m.cos_theta_o, -1.f, 1.f));
    for (const LightBounds* c : {&a, &b}) {
      const float theta_c = std::acos(std::clamp(c->cos_theta_o, -1.f, 1.f));
      const float between = std::acos(std::clamp(dot(m.w, c->w), -1.f, 1.f));
      // Every direction of c lies within theta_m of m's axis (no direction is more than pi away).
      EXPECT_LE(std::min(between + theta_c, kPi), theta_m + 1e-3f) << "case " << k;
    }
    EXPECT_EQ(m.phi, 2.f);
  }
}

// M_Ω of a single cosine emitter (θo = 0, θe = π/2) is π; of a sphere of normals, 4π (every
// direction with weight one).
TEST(LightTree, OrientationMeasureClosedForms) {
  LightBounds one_sided;
  one_sided.cos_theta_o = 1.f;
  one_sided.cos_theta_e = 0.f;
  EXPECT_NEAR(orientation_measure(one_sided), kPi, 1e-5);
  LightBounds all;
  all.cos_theta_o = -1.f;
  all.cos_theta_e = 0.f;
  EXPECT_NEAR(orientation_measure(all), 4.f * kPi, 1e-4);
}

}  // namespace
}  // namespace pathspace
