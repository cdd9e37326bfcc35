// Unit tests: the built-in Cornell scenes match docs/scenes.md (catalogue, geometry, lights).
#include <gtest/gtest.h>

#include "pathspace/accel/accel.h"
#include "pathspace/base/error.h"
#include "pathspace/scene/builtin_scenes.h"

namespace pathspace {
namespace {

TEST(BuiltinScenes, CatalogueByNameAndId) {
  const char* ids[] = {"e_c", "e_p", "bs_c", "gbs_c", "glm_c", "gbs_p", "gbs_b", "gbs_s"};
  const unsigned masks[] = {1, 4, 193, 449, 273, 452, 456, 450};
  for (int i = 0; i < 8; ++i) {
    const BuiltinSceneInfo* info = find_builtin_scene(ids[i]);
    ASSERT_NE(info, nullptr) << ids[i];
    EXPECT_EQ(info->mask, masks[i]);
    EXPECT_EQ(find_builtin_scene(info->name), info);
  }
  EXPECT_EQ(find_builtin_scene(kDefaultSceneName)->id, "bs_c");
  EXPECT_THROW(make_builtin_scene("no-such-scene"), Error);
}

TEST(BuiltinScenes, LightsAndGeometry) {
  const Scene box = make_builtin_scene("bs_c", 64, 64);
  EXPECT_EQ(box.lights.size(), 2u);  // the emitter is two triangles = two lights (§5)
  EXPECT_EQ(box.spheres.size(), 2u);
  EXPECT_EQ(box.triangles.size(), 10u + 10u);
  for (const Light& l : box.lights) {
    EXPECT_EQ(l.type, LightType::area_triangle);
    EXPECT_FLOAT_EQ(l.value.r, 25.03329895614464f);
    const Triangle& t = box.triangles[l.shape];
    const Vec3 n = triangle_normal(box.positions[t.v[0]], box.positions[t.v[1]], box.positions[t.v[2]]);
    EXPECT_NEAR(n.z, -1.f, 1e-6f);  // emits downwards
  }
  const Scene point = make_builtin_scene("gbs_p", 64, 64);
  ASSERT_EQ(point.lights.size(), 1u);
  EXPECT_EQ(point.lights[0].type, LightType::point);
  EXPECT_NEAR(point.lights[0].value.r * 4.f * kPi, 70.f, 1e-4f);
  EXPECT_EQ(point.triangles.size(), 10u);  // no light box
  const Scene sun = make_builtin_scene("gbs_s", 64, 64);
  EXPECT_EQ(sun.lights.size(), 1u);
  EXPECT_NEAR(sun.lights[0].direction.x, -0.48507125f, 1e-6f);
  EXPECT_NEAR(sun.bounds().radius, 2.21705961f, 1e-6f);
}

// An area light names its shape by index: one past the scene's triangles or spheres is an error
// of the scene, not a read past an array in every light sample.
TEST(BuiltinScenes, AreaLightOfAMissingShapeIsAnError) {
  Scene box = make_builtin_scene("bs_c", 64, 64);
  box.lights[1].shape = uint32_t(box.triangles.size());
  EXPECT_THROW(box.finalize(), Error);
  box.lights[1].type = LightType::area_sphere;
  box.lights[1].shape = uint32_t(box.spheres.size());
  EXPECT_THROW(box.finalize(), Error);
  box.lights[1].shape = uint32_t(box.spheres.size()) - 1;
  EXPECT_NO_THROW(box.finalize());
}

TEST(Accel, HitsBoxWallsAndSpheresFromBothSides) {
  const Scene scene = make_builtin_scene("bs_c", 64, 64);
  Accel accel(scene);
  SurfaceHit hit;
  // Straight down from the box centre hits the floor (normal +z).
  ASSERT_TRUE(accel.intersect(Ray{Vec3(0, 0, 0), Vec3(0, 0, -1), 0.f, kInfinity}, &hit));
  EXPECT_NEAR(hit.p.z, -1.28002f, 1e-5f);
  EXPECT_NEAR(hit.ng.z, 1.f, 1e-6f);
  // Into the glass sphere from outside, then from inside.
  const Sphere& glass = scene.spheres[1];
  const Vec3 o = glass.center + Vec3(0, -2.f, 0);
  ASSERT_TRUE(accel.intersect(Ray{o, Vec3(0, 1, 0), 0.f, kInfinity}, &hit));
  EXPECT_EQ(hit.kind, ShapeKind::sphere);
  EXPECT_NEAR(hit.t, 1.5f, 1e-5f);
  ASSERT_TRUE(accel.intersect(Ray{glass.center, Vec3(0, 1, 0), 0.f, kInfinity}, &hit));
  EXPECT_NEAR(hit.t, 0.5f, 1e-5f);
  EXPECT_NEAR(hit.ng.y, 1.f, 1e-5f);  // outward normal, ray leaves through the front
  EXPECT_TRUE(accel.occluded(Ray{Vec3(0, 0, 0), Vec3(0, 0, -1), 0.f, 10.f}));
  EXPECT_FALSE(accel.occluded(Ray{Vec3(0, 0, 0), Vec3(0, 0, -1), 0.f, 1.0f}));
  // Batched queries equal single ones.
  Ray rays[3] = {{Vec3(0, 0, 0), Vec3(0, 0, -1), 0.f, kInfinity}, {o, Vec3(0, 1, 0), 0.f, kInfinity},
                 {Vec3(0, -10, 0), Vec3(0, -1, 0), 0.f, kInfinity}};
  SurfaceHit hits[3];
  bool found[3];
  accel.intersect_batch(rays, hits, found, 3, false);
  for (int i = 0; i < 3; ++i) {
    SurfaceHit single;
    EXPECT_EQ(found[i], accel.intersect(rays[i], &single));
    if (found[i]) {
      EXPECT_EQ(hits[i].t, single.t);
    }
  }
}

}  // namespace
}  // namespace pathspace
