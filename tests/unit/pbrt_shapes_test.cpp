// pbrt-v4 shapes beyond triangle meshes and spheres: `disk` (tessellated with its area preserved,
// annulus and partial disks, uv), `bilinearmesh` (two triangles per patch, non-planar warning),
// `loopsubdiv` (triangle counts per level, normals, errors), and
// ObjectBegin / ObjectInstance (flattened: each instance adds the object's shapes with its own
// transform on top of theirs).
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "pathspace/base/error.h"
#include "pathspace/io/pbrt/pbrt_scene_builder.h"

namespace pathspace {
namespace {

Scene load_world(const std::string& world, std::vector<std::string>* warnings = nullptr) {
  std::vector<std::string> w;
  LoadWarnings lw(warnings ? warnings : &w);
  return pbrt::load_pbrt_string("LookAt 0 0 5  0 0 0  0 1 0\nCamera \"perspective\" \"float fov\" [ 40 ]\nWorldBegin\n" + world,
                                "test.pbrt", ".", {}, &lw, nullptr);
}

double mesh_area(const Scene& s) {
  double a = 0;
  for (const Triangle& t : s.triangles) a += triangle_area(s.positions[t.v[0]], s.positions[t.v[1]], s.positions[t.v[2]]);
  return a;
}

bool has_warning(const std::vector<std::string>& w, const std::string& part) {
  for (const std::string& m : w)
    if (m.find(part) != std::string::npos) return true;
  return false;
}

TEST(PbrtShapes, DiskKeepsItsAreaAndFacesPlusZ) {
  std::vector<std::string> w;
  const Scene s = load_world("Translate 0 0 1\nShape \"disk\" \"float radius\" 2 \"float height\" 0.5\n", &w);
  ASSERT_GT(s.triangles.size(), 32u);
  EXPECT_NEAR(mesh_area(s), M_PI * 4.0, 1e-4 * M_PI * 4.0);
  for (const Triangle& t : s.triangles) {
    const Vec3 n = triangle_normal(s.positions[t.v[0]], s.positions[t.v[1]], s.positions[t.v[2]]);
    EXPECT_NEAR(n.z, 1.f, 1e-5f);
    EXPECT_NEAR(s.positions[t.v[0]].z, 1.5f, 1e-6f);  // height 0.5, translated by 1
  }
  EXPECT_TRUE(has_warning(w, "disk tessellated")) << ::testing::PrintToString(w);
}

TEST(PbrtShapes, AnnulusAndPartialDisk) {
  const Scene ring = load_world("Shape \"disk\" \"float radius\" 2 \"float innerradius\" 1\n");
  EXPECT_NEAR(mesh_area(ring), M_PI * 3.0, 1e-4 * M_PI * 3.0);
  const Scene half = load_world("Shape \"disk\" \"float radius\" 1 \"float phimax\" 180\n");
  EXPECT_NEAR(mesh_area(half), M_PI / 2.0, 1e-4 * M_PI / 2.0);
  for (const Vec3& p : half.positions) EXPECT_GE(p.y, -1e-6f);
  EXPECT_THROW(load_world("Shape \"disk\" \"float radius\" 1 \"float innerradius\" 2\n"), Error);
}

TEST(PbrtShapes, DiskAreaLightEmitsThePowerOfTheDisk) {
  const Scene s = load_world("AttributeBegin\nAreaLightSource \"diffuse\" \"rgb L\" [ 3 3 3 ]\n"
                             "Shape \"disk\" \"float radius\" 0.5\nAttributeEnd\n");
  ASSERT_EQ(s.lights.size(), s.triangles.size());
  double area = 0;
  for (const Light& l : s.lights) {
    const Triangle& t = s.triangles[l.shape];
    area += triangle_area(s.positions[t.v[0]], s.positions[t.v[1]], s.positions[t.v[2]]);
  }
  EXPECT_NEAR(area, M_PI * 0.25, 1e-4);
}

TEST(PbrtShapes, BilinearMeshIsTwoTrianglesPerPatch) {
  std::vector<std::string> w;
  const Scene flat = load_world("Shape \"bilinearmesh\" \"point3 P\" [ 0 0 0  2 0 0  0 3 0  2 3 0 ]\n", &w);
  ASSERT_EQ(flat.triangles.size(), 2u);
  EXPECT_NEAR(mesh_area(flat), 6.0, 1e-5);
  EXPECT_FALSE(has_warning(w, "non-planar"));
  const Scene bent = load_world("Shape \"bilinearmesh\" \"point3 P\" [ 0 0 0  1 0 0  0 1 0  1 1 1 ] \"integer indices\" [ 0 1 2 3 ]\n", &w);
  EXPECT_EQ(bent.triangles.size(), 2u);
  EXPECT_TRUE(has_warning(w, "non-planar"));
  EXPECT_THROW(load_world("Shape \"bilinearmesh\" \"point3 P\" [ 0 0 0  1 0 0  0 1 0 ] \"integer indices\" [ 0 1 2 5 ]\n"), Error);
}

TEST(PbrtShapes, LoopSubdivisionIsSubdividedToItsLevel) {
  // A tetrahedron: 4 triangles, 4^2 each at levels 2, with smooth normals and no warning.
  const std::string tetra = "\"point3 P\" [ 1 1 1  -1 -1 1  -1 1 -1  1 -1 -1 ] \"integer indices\" [ 0 1 2  0 3 1  0 2 3  1 3 2 ]";
  std::vector<std::string> w;
  const Scene s = load_world("Shape \"loopsubdiv\" \"integer levels\" 2 " + tetra + "\n", &w);
  EXPECT_EQ(s.triangles.size(), 4u * 16u);
  EXPECT_FALSE(s.normals.empty());
  EXPECT_FALSE(has_warning(w, "loopsubdiv"));
  const Scene d = load_world("Shape \"loopsubdiv\" " + tetra + "\n");  // pbrt's default: 3 levels
  EXPECT_EQ(d.triangles.size(), 4u * 64u);
  EXPECT_THROW(load_world("Shape \"loopsubdiv\" \"integer levels\" 20 " + tetra + "\n"), Error);
  EXPECT_THROW(load_world("Shape \"loopsubdiv\" \"point3 P\" [ 0 0 0  1 0 0  0 1 0 ] \"integer indices\" [ 0 1 3 ]\n"), Error);
}

TEST(PbrtShapes, ObjectInstancesAreFlattenedWithBothTransforms) {
  const std::string object =
      "ObjectBegin \"tri\"\nTranslate 0 0 1\nShape \"trianglemesh\" \"point3 P\" [ 0 0 0  1 0 0  0 1 0 ] \"integer indices\" [ 0 1 2 ]\n"
      "ObjectEnd\n";
  const Scene none = load_world(object);
  EXPECT_EQ(none.triangles.size(), 0u);  // a definition alone adds nothing
  const Scene s = load_world(object + "AttributeBegin\nTranslate 10 0 0\nObjectInstance \"tri\"\nAttributeEnd\n"
                                      "AttributeBegin\nScale 2 2 2\nObjectInstance \"tri\"\nAttributeEnd\n");
  ASSERT_EQ(s.triangles.size(), 2u);
  const Vec3 a = s.positions[s.triangles[0].v[0]], b = s.positions[s.triangles[1].v[0]];
  EXPECT_NEAR(distance(a, Vec3(10, 0, 1)), 0.f, 1e-5f);  // instance translation on top of the object's
  EXPECT_NEAR(distance(b, Vec3(0, 0, 2)), 0.f, 1e-5f);   // the object's translation scaled by the instance
  EXPECT_NEAR(mesh_area(s), 0.5 + 2.0, 1e-5);
  EXPECT_THROW(load_world("ObjectInstance \"missing\"\n"), Error);
  EXPECT_THROW(load_world("ObjectBegin \"a\"\nObjectInstance \"a\"\nObjectEnd\n"), Error);
}

}  // namespace
}  // namespace pathspace
