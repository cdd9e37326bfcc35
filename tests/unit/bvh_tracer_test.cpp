// The device tracer over the flat BVH (accel/bvh_tracer.h, accel/bvh_build.h) against Embree
// (Accel): the same nearest hits and shadow answers on random, axis-aligned, camera and surface
// rays, the (tmin, tmax) interval, path-traced images path by path, and the degenerate scenes.
// The two use different triangle tests (Woop et al.'s watertight test, Embree's own), so a ray
// through a shared edge or vertex may be given to either triangle, and t, u, v differ by rounding:
// such rays are counted, not forbidden, and must stay below 1e-4 of all. Hits of different
// primitives at the same t (coplanar overlapping faces) are ties, counted apart. The wide BVH
// (accel/wide_bvh.h) collapsed from the same tree tests the same primitives with the same code, so
// on every ray it must find the binary tracer's nearest t exactly (its primitive too, but for ties)
// and give every shadow ray the same answer.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "pathspace/accel/accel.h"
#include "pathspace/accel/bvh_build.h"
#include "pathspace/accel/bvh_tracer.h"
#include "pathspace/accel/wide_bvh_build.h"
#include "pathspace/integrators/common/camera_sample.h"
#include "pathspace/integrators/pt/pt_kernel.h"
#include "pathspace/sampling/rng.h"
#include "pathspace/sampling/warps.h"
#include "pathspace/scene/builtin_scenes.h"
#include "pathspace/io/scene_loader.h"
#include "support/shared_data.h"
#include "support/shipped_scenes.h"

#ifndef PATHSPACE_SHARED_SCENES_DIR
#define PATHSPACE_SHARED_SCENES_DIR ""
#endif

namespace pathspace {
namespace {

constexpr double kMaxDisagreement = 1e-4;  // fraction of rays whose answers may differ (edges)
// Fraction of rays that may meet two coplanar overlapping surfaces at one t (the shipped scenes'
// boxes stand on the floor with their bottom faces in it: about 0.2% of the rays there); either
// surface is a right answer.
constexpr double kMaxTies = 1e-2;

struct Traced {
  const Scene& scene;
  SceneView view = scene.view();
  Accel accel{scene};
  FlatBvh bvh = build_bvh(view);
  BvhTracer tracer{view, bvh.view()};
  WideBvh wide = build_wide_bvh(bvh);
  WideBvhTracer wide_tracer{view, wide.view()};
};

// Rays from random points in the scene's bounds in random directions (one in eight along an axis
// or in an axis plane: zero direction components), camera rays through random raster points, and
// rays leaving Embree's hits of those camera rays, as a path tracer spawns them.
std::vector<Ray> test_rays(const Traced& t, size_t count, uint64_t seed) {
  Pcg32 rng(seed, 7);
  const Bounds3 b = t.scene.geometry_bounds();
  const auto inside = [&] {
    const Vec3 e = b.diagonal();
    return b.lo + Vec3(e.x * rng.next_float(), e.y * rng.next_float(), e.z * rng.next_float());
  };
  std::vector<Ray> rays;
  rays.reserve(count);
  while (rays.size() < count) {
    const uint32_t kind = rng.next_u32() % 8;
    Vec3 d = square_to_uniform_sphere({rng.next_float(), rng.next_float()});
    if (kind == 0) {
      const int zeros = int(rng.next_u32() % 2) + 1;  // one or two zero components
      for (int k = 0, axis = int(rng.next_u32() % 3); k < zeros; ++k) d[(axis + k) % 3] = 0.f;
      d = normalize(d);
    }
    if (kind <= 3) {
      rays.push_back(Ray{inside(), d, 0.f, kInfinity});
      continue;
    }
    const PerspectiveCamera& cam = t.scene.camera;
    const Ray camera = cam.generate_ray(float(cam.width) * rng.next_float(), float(cam.height) * rng.next_float());
    rays.push_back(camera);
    SurfaceHit hit;
    if (kind >= 6 && t.accel.intersect(camera, &hit)) rays.push_back(spawn_ray(hit.p, hit.ng, d, t.scene.ray_epsilon, 0.f));
  }
  rays.resize(count);
  if (t.view.positions_end)  // a scene that moves: each ray at its own time in the shutter
    for (Ray& r : rays) r.time = rng.next_float();
  return rays;
}

bool close_vec(const Vec3& a, const Vec3& b, float tol) { return length(a - b) <= tol * (1.f + length(b)); }

struct Agreement {
  size_t rays = 0, hits = 0, disagree = 0;
  size_t ties = 0;  // both hit different primitives at the same t: coplanar overlapping surfaces
};

bool same_t(float t, float t_embree) { return std::fabs(t - t_embree) <= 1e-4f * t_embree + 1e-6f; }

// Nearest hits: the same found / not found, primitive and kind; then t, p, normals, uv and records.
Agreement compare_intersect(const Traced& t, const std::vector<Ray>& rays) {
  Agreement a;
  for (const Ray& ray : rays) {
    SurfaceHit e, h;
    const bool fe = t.accel.intersect(ray, &e), fh = t.tracer.intersect(ray, &h);
    ++a.rays;
    if (fe && fh && (e.prim != h.prim || e.kind != h.kind) && same_t(h.t, e.t)) {
      ++a.ties;  // either is right; which one is found depends on the order of the tests
      continue;
    }
    if (fe != fh || (fe && (e.prim != h.prim || e.kind != h.kind))) {
      ++a.disagree;
      continue;
    }
    if (!fe) continue;
    ++a.hits;
    EXPECT_TRUE(same_t(h.t, e.t)) << h.t << " vs " << e.t << ", prim " << e.prim << " kind " << int(e.kind);
    EXPECT_TRUE(close_vec(h.p, e.p, 1e-4f)) << "prim " << e.prim;
    EXPECT_TRUE(close_vec(h.ng, e.ng, 1e-5f)) << "prim " << e.prim;
    EXPECT_TRUE(close_vec(h.ns, e.ns, 1e-3f)) << "prim " << e.prim;
    EXPECT_NEAR(h.u, e.u, 1e-3f);
    EXPECT_NEAR(h.v, e.v, 1e-3f);
    EXPECT_NEAR(h.uv.x, e.uv.x, 1e-3f);
    EXPECT_NEAR(h.uv.y, e.uv.y, 1e-3f);
    EXPECT_EQ(h.material, e.material);
    EXPECT_EQ(h.light, e.light);
  }
  return a;
}

// Shadow rays between random points of the bounds, of random finite length.
Agreement compare_occluded(const Traced& t, const std::vector<Ray>& rays, uint64_t seed) {
  Pcg32 rng(seed, 11);
  const float diagonal = length(t.scene.geometry_bounds().diagonal());
  Agreement a;
  for (Ray ray : rays) {
    SurfaceHit e;
    const float reach = t.accel.intersect(ray, &e) ? e.t : diagonal;
    ray.tmax = reach * (0.5f + rng.next_float());  // about half end before the nearest hit
    const bool be = t.accel.occluded(ray), bh = t.tracer.occluded(ray);
    ++a.rays;
    a.hits += be;
    if (be != bh) ++a.disagree;
  }
  return a;
}

// The wide tracer against the binary one: nearest hits (found, t to the bit, primitive but for
// ties) and shadow rays of random lengths; returns the rays whose answers differ.
size_t wide_differences(const Traced& t, const std::vector<Ray>& rays, uint64_t seed) {
  Pcg32 rng(seed, 13);
  size_t differ = 0;
  for (Ray ray : rays) {
    SurfaceHit b, w;
    const bool fb = t.tracer.intersect(ray, &b), fw = t.wide_tracer.intersect(ray, &w);
    if (fb != fw || (fb && (std::memcmp(&b.t, &w.t, sizeof b.t) != 0 || ((b.prim != w.prim || b.kind != w.kind) && b.t != w.t)))) {
      ++differ;
      continue;
    }
    ray.tmax = (fb ? b.t : 1.f) * (0.5f + rng.next_float());
    if (t.tracer.occluded(ray) != t.wide_tracer.occluded(ray)) ++differ;
  }
  return differ;
}

void expect_agreement(const Scene& scene, const std::string& name, size_t count) {
  SCOPED_TRACE(name);
  const Traced t{scene};
  const std::vector<Ray> rays = test_rays(t, count, 1);
  const Agreement hits = compare_intersect(t, rays);
  EXPECT_LE(double(hits.disagree), kMaxDisagreement * double(hits.rays)) << hits.disagree << " of " << hits.rays;
  EXPECT_LE(double(hits.ties), kMaxTies * double(hits.rays)) << hits.ties << " of " << hits.rays;
  EXPECT_GT(hits.hits, hits.rays / 4);
  const Agreement shadows = compare_occluded(t, rays, 2);
  EXPECT_LE(double(shadows.disagree), kMaxDisagreement * double(shadows.rays)) << shadows.disagree << " of " << shadows.rays;
  EXPECT_GT(shadows.hits, shadows.rays / 8);
  EXPECT_LT(shadows.hits, shadows.rays);
  std::printf("%s: %u nodes, %u refs, depth %u, %.2f ms; of %zu rays, %zu nearest hits differ (%zu ties), %zu shadow answers\n",
              name.c_str(), t.bvh.stats.nodes, t.bvh.stats.prim_refs, t.bvh.stats.max_depth, 1e3 * t.bvh.stats.build_seconds,
              hits.rays, hits.disagree, hits.ties, shadows.disagree);
  EXPECT_EQ(wide_differences(t, rays, 3), 0u) << "wide BVH against the binary one";
  std::printf("%s wide: %u nodes, %.2f children each, depth %u\n", name.c_str(), t.wide.stats.nodes, t.wide.stats.mean_children,
              t.wide.stats.max_depth);
}

TEST(BvhTracer, HitsAgreeWithEmbreeOnTheBuiltinScenes) {
  for (const char* name : {"cornell-box", "cornell-glossy-large-mirror", "cornell-empty-area", "filter-leak", "filter-fence"})
    expect_agreement(make_builtin_scene(name, 64, 64), name, 100000);
}

TEST(BvhTracer, HitsAgreeWithEmbreeOnTheShippedScenes) {
  for (const char* name : {"textured-room", "glass-caustic"}) {
    std::vector<std::string> warnings;
    const Scene scene = testing::load_shipped(testing::shipped_scene(name), "scene.pbrt", 64, 64, &warnings);
    if (std::string(name) == "textured-room") {
      EXPECT_FALSE(scene.textures.empty());
    }
    expect_agreement(scene, name, 100000);
  }
}

// Cutouts (scene/surface_opacity.h): both tracers skip the same triangles for the same rays. Every
// material of the Cornell box gets opacity 0.6, the back wall's a texture of opacities.
TEST(BvhTracer, CutoutsAgreeWithEmbree) {
  Scene scene = make_builtin_scene("cornell-box", 64, 64);
  ImageTexture t;
  t.name = "opacity";
  t.width = t.height = 4;
  for (int i = 0; i < 16; ++i) t.texels.push_back(Rgb(float(i % 5) / 4.f));
  const int32_t texture = int32_t(scene.add_texture(t));
  for (Material& m : scene.materials) m.opacity = 0.6f;
  scene.materials[scene.triangles[0].material].opacity_texture = texture;
  scene.finalize();
  ASSERT_TRUE(scene.view().has_cutouts);
  expect_agreement(scene, "cornell-box with cutouts", 100000);
}

// Motion blur (scene/motion.h): the floor rises, the back wall tilts and the light box slides while
// the shutter is open; rays at random times meet the same triangles, where they are then.
TEST(BvhTracer, MovingGeometryAgreesWithEmbree) {
  Scene scene = make_builtin_scene("cornell-box", 64, 64);
  scene.positions_end = scene.positions;
  for (uint32_t v : scene.triangles[0].v) scene.positions_end[v].z += 0.2f;
  for (uint32_t v : scene.triangles[1].v) scene.positions_end[v].z += 0.2f;
  for (uint32_t v : scene.triangles[2].v) scene.positions_end[v].y -= 0.1f * (scene.positions[v].z + 1.3f);
  for (size_t t = scene.triangles.size() - kLightBoxTriangles; t < scene.triangles.size(); ++t)
    for (uint32_t v : scene.triangles[t].v) scene.positions_end[v] = scene.positions[v] + Vec3(0.6f, 0.f, 0.f);
  scene.finalize();
  ASSERT_NE(scene.view().positions_end, nullptr);
  expect_agreement(scene, "cornell-box moving", 100000);
}

// Larger scenes (outside the repository, docs/testing.md): deeper trees with many spatial splits.
TEST(BvhTracer, HitsAgreeWithEmbreeOnBitterliScenes) {
  for (const char* name : {"veach-bidir", "living-room"}) {
    const std::string path = std::string(PATHSPACE_SHARED_SCENES_DIR) + "/bitterli/" + name + "/scene-v4.pbrt";
    PATHSPACE_REQUIRE_SHARED_DATA(path);
    SceneLoadOptions options;
    options.width = options.height = 64;
    options.substitute_missing_textures = true;  // the living room lacks three files
    std::vector<std::string> warnings;
    expect_agreement(load_scene(path, options, &warnings), name, 50000);
  }
}

// Every primitive is in some leaf, leaves hold at most kBvhMaxLeafSize, and the depth fits the stack.
TEST(BvhTracer, TheFlatTreeReferencesEveryPrimitive) {
  const Scene scene = make_builtin_scene("filter-fence", 16, 16);
  const FlatBvh bvh = build_bvh(scene.view());
  std::vector<int> seen_tri(scene.triangles.size()), seen_sph(scene.spheres.size());
  size_t leaves = 0;
  for (const BvhNode& n : bvh.nodes)
    for (int32_t c : n.child) {
      if (c >= 0) {
        EXPECT_LT(uint32_t(c), bvh.nodes.size());
        continue;
      }
      ++leaves;
      EXPECT_GE(bvh_leaf_count(c), 1u);
      EXPECT_LE(bvh_leaf_count(c), kBvhMaxLeafSize);
      for (uint32_t i = bvh_leaf_first(c); i < bvh_leaf_first(c) + bvh_leaf_count(c); ++i) {
        const uint32_t ref = bvh.prims[i];
        (bvh_ref_kind(ref) == ShapeKind::triangle ? seen_tri : seen_sph)[bvh_ref_index(ref)] = 1;
      }
    }
  EXPECT_EQ(leaves, bvh.stats.leaves);
  EXPECT_EQ(bvh.stats.nodes + 1, leaves);  // a binary tree
  EXPECT_EQ(std::count(seen_tri.begin(), seen_tri.end(), 0), 0);
  EXPECT_EQ(std::count(seen_sph.begin(), seen_sph.end(), 0), 0);
  EXPECT_GE(bvh.stats.prim_refs, scene.triangles.size() + scene.spheres.size());
  EXPECT_LT(int(bvh.stats.max_depth), kBvhStackSize);
}

// Nothing is found before tmin or at or after tmax: a ray ending just short of the nearest hit finds
// nothing, and one starting just past it finds what Embree finds from there.
TEST(BvhTracer, HonoursTheRayInterval) {
  const Scene scene = make_builtin_scene("cornell-box", 32, 32);
  const Traced t{scene};
  int checked = 0;
  for (const Ray& ray : test_rays(t, 5000, 3)) {
    SurfaceHit h;
    if (!t.tracer.intersect(ray, &h)) continue;
    ++checked;
    Ray shorter = ray;
    shorter.tmax = h.t * 0.999f;
    SurfaceHit none;
    EXPECT_FALSE(t.tracer.intersect(shorter, &none));
    EXPECT_FALSE(t.tracer.occluded(shorter));
    Ray past = ray;
    past.tmin = h.t * 1.001f;
    SurfaceHit e, b;
    const bool fe = t.accel.intersect(past, &e), fb = t.tracer.intersect(past, &b);
    EXPECT_EQ(fe, fb);
    if (fe && fb) {
      EXPECT_GT(b.t, past.tmin);
    }
  }
  EXPECT_GT(checked, 4000);
}

// Plain path tracing through either tracer with the same samplers: the same estimator, and nearly
// every path meets the same surfaces. Not bit for bit: t, u, v round differently in the two triangle
// tests, which moves hit points and directions in their last bits (most path values differ there),
// so a path "agrees" when its value is within a relative 1e-4; at least 99.9% of the 262144 must.
// The rest (a bounce near an edge or a Russian roulette threshold that went the other way) are
// samples of the same estimator: the means then differ by at most 0.1% of the paths times the
// largest path values' difference, and in practice by far less; 1e-3 relative is a loose check of
// the sums, the count of agreeing paths is the test.
TEST(BvhTracer, PathTracedImageMatchesEmbreePathByPath) {
  const Scene scene = make_builtin_scene("cornell-box", 64, 64);
  const Traced t{scene};
  const PtSettings settings;
  size_t identical = 0, agree = 0, total = 0;
  double sum_e = 0.0, sum_b = 0.0;
  const auto near = [](float b, float e) { return std::fabs(b - e) <= 1e-4f * std::fabs(e) + 1e-7f; };
  for (uint32_t pixel = 0; pixel < 64 * 64; ++pixel)
    for (uint64_t s = 0; s < 64; ++s) {
      const Sampler sampler(5, pixel, s);
      const Ray ray = sample_camera_ray(t.view.camera, sampler, pixel, 0.f);
      PathCounters ce, cb;
      const Rgb e = pt_trace_path(t.view, t.accel, sampler, ray, settings, &ce);
      const Rgb b = pt_trace_path(t.view, t.tracer, sampler, ray, settings, &cb);
      identical += std::memcmp(&e, &b, sizeof e) == 0;
      agree += near(b.r, e.r) && near(b.g, e.g) && near(b.b, e.b);
      ++total;
      sum_e += double(e.r) + double(e.g) + double(e.b);
      sum_b += double(b.r) + double(b.g) + double(b.b);
    }
  EXPECT_GE(double(agree), 0.999 * double(total)) << total - agree << " paths differ";
  EXPECT_NEAR(sum_b / double(total), sum_e / double(total), 1e-3 * sum_e / double(total));
  std::printf("%zu of %zu paths differ by more than 1e-4 (%zu bit-identical); mean %.7f (Embree) %.7f (BVH)\n",
              total - agree, total, identical, sum_e / double(total), sum_b / double(total));
}

TEST(BvhTracer, EmptySceneHasNoNodesAndNoHits) {
  const SceneView empty;
  const FlatBvh bvh = build_bvh(empty);
  EXPECT_TRUE(bvh.nodes.empty());
  EXPECT_TRUE(bvh.prims.empty());
  const BvhTracer tracer{empty, bvh.view()};
  SurfaceHit hit;
  EXPECT_FALSE(tracer.intersect(Ray{Vec3(0.f), Vec3(0.f, 0.f, 1.f), 0.f, kInfinity}, &hit));
  EXPECT_FALSE(tracer.occluded(Ray{Vec3(0.f), Vec3(0.f, 0.f, 1.f), 0.f, kInfinity}));
}

// One sphere (a tree that is one leaf): hits from outside and inside, misses, and the interval.
TEST(BvhTracer, SingleSphere) {
  const Sphere sphere{Vec3(1.f, 2.f, 3.f), 0.5f, 7, 2, false};
  SceneView view;
  view.spheres = &sphere;
  view.num_spheres = 1;
  const FlatBvh bvh = build_bvh(view);
  ASSERT_EQ(bvh.nodes.size(), 1u);
  const BvhTracer tracer{view, bvh.view()};
  SurfaceHit hit;
  ASSERT_TRUE(tracer.intersect(Ray{Vec3(1.f, 2.f, 0.f), Vec3(0.f, 0.f, 1.f), 0.f, kInfinity}, &hit));
  EXPECT_NEAR(hit.t, 2.5f, 1e-6f);
  EXPECT_EQ(hit.kind, ShapeKind::sphere);
  EXPECT_EQ(hit.material, 7u);
  EXPECT_EQ(hit.light, 2);
  EXPECT_TRUE(close_vec(hit.ng, Vec3(0.f, 0.f, -1.f), 1e-6f));
  ASSERT_TRUE(tracer.intersect(Ray{Vec3(1.f, 2.f, 3.f), Vec3(1.f, 0.f, 0.f), 0.f, kInfinity}, &hit));  // from inside
  EXPECT_NEAR(hit.t, 0.5f, 1e-6f);
  EXPECT_FALSE(tracer.intersect(Ray{Vec3(1.f, 2.f, 0.f), Vec3(0.f, 0.f, -1.f), 0.f, kInfinity}, &hit));
  EXPECT_FALSE(tracer.intersect(Ray{Vec3(2.f, 2.f, 0.f), Vec3(0.f, 0.f, 1.f), 0.f, kInfinity}, &hit));
  EXPECT_FALSE(tracer.occluded(Ray{Vec3(1.f, 2.f, 0.f), Vec3(0.f, 0.f, 1.f), 0.f, 2.4f}));
  EXPECT_TRUE(tracer.occluded(Ray{Vec3(1.f, 2.f, 0.f), Vec3(0.f, 0.f, 1.f), 0.f, 2.6f}));
}

// A unit square of two triangles: hits at known barycentrics (u, v of vertices 1 and 2, as Embree
// reports them) from both sides, and no ray through the shared diagonal slips between the two
// (the watertight test's point; the diagonal's points are mostly not representable exactly).
TEST(BvhTracer, TwoTrianglesBarycentricsAndTheSharedEdge) {
  const Vec3 positions[4] = {Vec3(0.f, 0.f, 0.f), Vec3(1.f, 0.f, 0.f), Vec3(0.f, 1.f, 0.f), Vec3(1.f, 1.f, 0.f)};
  const Triangle tris[2] = {{{0, 1, 2}, 3}, {{1, 3, 2}, 4}};
  SceneView view;
  view.positions = positions;
  view.triangles = tris;
  view.num_triangles = 2;
  const FlatBvh bvh = build_bvh(view);
  ASSERT_EQ(bvh.nodes.size(), 1u);
  const BvhTracer tracer{view, bvh.view()};
  SurfaceHit hit;
  for (const float dz : {1.f, -1.f}) {  // both sides: no backface culling
    ASSERT_TRUE(tracer.intersect(Ray{Vec3(0.25f, 0.5f, -dz), Vec3(0.f, 0.f, dz), 0.f, kInfinity}, &hit));
    EXPECT_EQ(hit.prim, 0u);
    EXPECT_NEAR(hit.t, 1.f, 1e-6f);
    EXPECT_NEAR(hit.u, 0.25f, 1e-6f);
    EXPECT_NEAR(hit.v, 0.5f, 1e-6f);
    EXPECT_TRUE(close_vec(hit.ng, Vec3(0.f, 0.f, 1.f), 1e-6f));
  }
  EXPECT_FALSE(tracer.intersect(Ray{Vec3(1.25f, 0.5f, -1.f), Vec3(0.f, 0.f, 1.f), 0.f, kInfinity}, &hit));
  Pcg32 rng(9, 9);
  int missed = 0;
  for (int i = 0; i < 100000; ++i) {
    const float x = 0.01f + 0.98f * rng.next_float();  // away from the square's corners
    const Vec3 target(x, 1.f - x, 0.f);
    const Vec3 o = target + square_to_uniform_sphere({rng.next_float(), rng.next_float()}) * 3.f;
    missed += !tracer.intersect(Ray{o, normalize(target - o), 0.f, kInfinity}, &hit);
  }
  EXPECT_EQ(missed, 0);
}

}  // namespace
}  // namespace pathspace
