// Two-level acceleration structures of animated scenes (accel/accel.h): a scene with moving parts is
// built as a static and a moving instance, and the next frame reuses the static one. Every hit must
// equal that of the flat, single-level structure of the same scene, bit for bit, and the static part
// is reused only when it is unchanged.
#include <gtest/gtest.h>

#include <cstring>

#include "pathspace/accel/accel.h"
#include "pathspace/sampling/hash.h"
#include "pathspace/scene/builtin_scenes.h"

namespace pathspace {
namespace {

Scene flat_copy(Scene s) {
  s.first_moving_triangle = Scene::kNothingMoves;
  s.first_moving_sphere = Scene::kNothingMoves;
  return s;
}

bool same(const SurfaceHit& a, const SurfaceHit& b) {
  const auto eq = [](const auto& x, const auto& y) { return std::memcmp(&x, &y, sizeof x) == 0; };
  return eq(a.p, b.p) && eq(a.ng, b.ng) && eq(a.ns, b.ns) && eq(a.t, b.t) && eq(a.u, b.u) && eq(a.v, b.v) && a.prim == b.prim &&
         a.kind == b.kind && a.material == b.material && a.light == b.light;
}

// Rays from random points inside the box in random directions, nearest hits and shadow queries.
void expect_same_hits(const Accel& tested, const Accel& flat, uint64_t seed) {
  int triangles = 0, spheres = 0;
  for (uint64_t i = 0; i < 20000; ++i) {
    const uint64_t h = mix64(seed * 1000003 + i);
    const auto u = [&](int k) { return bits_to_unit_float(mix64(h + uint64_t(k))); };
    const Vec3 o(2.4f * u(0) - 1.2f, 2.4f * u(1) - 1.2f, 2.4f * u(2) - 1.2f);
    const Vec3 d = normalize(Vec3(u(3) - 0.5f, u(4) - 0.5f, u(5) - 0.5f));
    const Ray ray(o, d, 1e-4f, kInfinity);
    SurfaceHit a, b;
    const bool ha = tested.intersect(ray, &a), hb = flat.intersect(ray, &b);
    ASSERT_EQ(ha, hb) << i;
    if (ha) {
      ASSERT_TRUE(same(a, b)) << "ray " << i;
      (a.kind == ShapeKind::sphere ? spheres : triangles)++;
    }
    const Ray shadow(o, d, 1e-4f, 1.5f);
    ASSERT_EQ(tested.occluded(shadow), flat.occluded(shadow)) << i;
  }
  EXPECT_GT(triangles, 1000);
  EXPECT_GT(spheres, 100);
}

TEST(AccelInstancing, MovingPartsHitExactlyLikeTheFlatStructure) {
  for (const char* name : {"cornell-moving-light", "cornell-moving-sphere"}) {
    const Scene frame0 = make_builtin_scene_at(name, 16, 16, 0.0), frame1 = make_builtin_scene_at(name, 16, 16, 0.7);
    const Accel a0(frame0);
    EXPECT_FALSE(a0.reused_static_part());
    const Accel a1(frame1, &a0);
    EXPECT_TRUE(a1.reused_static_part()) << name;
    const Scene flat0 = flat_copy(frame0), flat1 = flat_copy(frame1);
    expect_same_hits(a0, Accel(flat0), 1);
    expect_same_hits(a1, Accel(flat1), 2);
  }
}

// A camera moving through a still scene: frames after the first keep a static part, all of the
// scene (traced without an instance level), and from the third frame on it is reused whole.
TEST(AccelInstancing, StillScenesAreReusedWholeFromTheThirdFrame) {
  const Scene scene = make_builtin_scene("cornell-box", 16, 16);  // nothing moves
  const Accel a0(scene);
  const Accel a1(scene, &a0);  // a0 is flat: the static part is built here
  EXPECT_FALSE(a1.reused_static_part());
  const Accel a2(scene, &a1);
  EXPECT_TRUE(a2.reused_static_part());
  const Scene flat = flat_copy(scene);
  expect_same_hits(a2, Accel(flat), 4);
}

TEST(AccelInstancing, ChangedStaticGeometryIsBuiltAgain) {
  const Scene frame0 = make_builtin_scene_at("cornell-moving-light", 16, 16, 0.0);
  Scene frame1 = make_builtin_scene_at("cornell-moving-light", 16, 16, 0.5);
  frame1.positions[0].x += 0.01f;  // a wall's vertex: the static part is no longer the same
  const Accel a0(frame0);
  const Accel a1(frame1, &a0);
  EXPECT_FALSE(a1.reused_static_part());
  const Scene flat1 = flat_copy(frame1);
  expect_same_hits(a1, Accel(flat1), 3);
}

}  // namespace
}  // namespace pathspace
