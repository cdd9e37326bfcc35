// Loop subdivision (geometry/loop_subdivision.h): an icosahedron's subdivided surface has the area
// and volume of its limit surface (a level 7 stand-in) within 1% at level 4, it stays watertight and
// consistently oriented, a planar mesh with a border stays planar with its border, and bad input is
// an error. The pbrt shape `loopsubdiv` loads through it (pbrt_shapes_test.cpp).
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <utility>
#include <vector>

#include "pathspace/base/error.h"
#include "pathspace/geometry/loop_subdivision.h"

namespace pathspace {
namespace {

// The 12 vertices and 20 outward-facing triangles of an icosahedron of circumradius 1.
void icosahedron(std::vector<Vec3>* p, std::vector<uint32_t>* idx) {
  const float t = (1.f + std::sqrt(5.f)) / 2.f, s = 1.f / std::sqrt(1.f + t * t);
  *p = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t}, {0, -1, -t}, {0, 1, -t},
        {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  for (Vec3& v : *p) v = v * s;
  *idx = {0, 11, 5, 0, 5, 1, 0, 1, 7, 0, 7, 10, 0, 10, 11, 1, 5, 9, 5, 11, 4, 11, 10, 2, 10, 7, 6, 7, 1, 8,
          3, 9, 4, 3, 4, 2, 3, 2, 6, 3, 6, 8, 3, 8, 9, 4, 9, 5, 2, 4, 11, 6, 2, 10, 8, 6, 7, 9, 8, 1};
}

struct AreaVolume {
  double area = 0, volume = 0;
};

AreaVolume measure(const SubdividedMesh& m) {
  AreaVolume r;
  for (size_t i = 0; i < m.indices.size(); i += 3) {
    const Vec3 a = m.positions[m.indices[i]], b = m.positions[m.indices[i + 1]], c = m.positions[m.indices[i + 2]];
    r.area += 0.5 * double(length(cross(b - a, c - a)));
    r.volume += double(dot(a, cross(b, c))) / 6.0;  // signed: positive for an outward-facing closed mesh
  }
  return r;
}

// Every directed edge once, and its reverse once: closed and consistently oriented.
bool watertight(const SubdividedMesh& m) {
  std::map<std::pair<uint32_t, uint32_t>, int> directed;
  for (size_t i = 0; i < m.indices.size(); i += 3)
    for (size_t k = 0; k < 3; ++k) ++directed[{m.indices[i + k], m.indices[i + (k + 1) % 3]}];
  for (const auto& [edge, count] : directed) {
    if (count != 1) return false;
    const auto reverse = directed.find({edge.second, edge.first});
    if (reverse == directed.end() || reverse->second != 1) return false;
  }
  return true;
}

TEST(LoopSubdivision, IcosahedronAtLevel4MatchesTheLimitSurface) {
  std::vector<Vec3> p;
  std::vector<uint32_t> idx;
  icosahedron(&p, &idx);
  const SubdividedMesh level4 = loop_subdivide(p, idx, 4);
  const SubdividedMesh level7 = loop_subdivide(p, idx, 7);
  ASSERT_EQ(level4.indices.size(), 20u * 256u * 3u);
  ASSERT_EQ(level7.indices.size(), 20u * 16384u * 3u);
  EXPECT_TRUE(watertight(level4));
  EXPECT_TRUE(watertight(level7));
  const AreaVolume a = measure(level4), limit = measure(level7);
  EXPECT_GT(limit.volume, 0.0);  // outward-facing
  EXPECT_NEAR(a.area, limit.area, 0.01 * limit.area);
  EXPECT_NEAR(a.volume, limit.volume, 0.01 * limit.volume);
  // The limit surface of a regular icosahedron is close to a sphere inside it: every limit point is
  // within a few percent of a common radius.
  double lo = 1e9, hi = 0;
  for (const Vec3& v : level7.positions) lo = std::fmin(lo, double(length(v))), hi = std::fmax(hi, double(length(v)));
  EXPECT_LT(hi / lo, 1.05);
  EXPECT_LT(hi, 1.0);  // subdivision shrinks a convex mesh
  // Normals: unit length and pointing outwards.
  ASSERT_EQ(level4.normals.size(), level4.positions.size());
  for (size_t i = 0; i < level4.normals.size(); ++i) {
    EXPECT_NEAR(length(level4.normals[i]), 1.f, 1e-5f);
    EXPECT_GT(dot(level4.normals[i], normalize(level4.positions[i])), 0.95f);
  }
}

TEST(LoopSubdivision, APlanarMeshWithABorderStaysPlanar) {
  // A 2 x 2 grid of quads (9 vertices, 8 triangles) in the plane z = 0.
  std::vector<Vec3> p;
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 3; ++x) p.push_back(Vec3(float(x), float(y), 0.f));
  std::vector<uint32_t> idx;
  for (uint32_t y = 0; y < 2; ++y)
    for (uint32_t x = 0; x < 2; ++x) {
      const uint32_t a = y * 3 + x, b = a + 1, c = a + 3, d = a + 4;
      idx.insert(idx.end(), {a, b, d, a, d, c});
    }
  const SubdividedMesh m = loop_subdivide(p, idx, 3);
  EXPECT_EQ(m.indices.size(), 8u * 64u * 3u);
  for (const Vec3& v : m.positions) {
    EXPECT_EQ(v.z, 0.f);
    EXPECT_GE(v.x, 0.f);  // the border stays a border: nothing leaves the square
    EXPECT_LE(v.x, 2.f);
    EXPECT_GE(v.y, 0.f);
    EXPECT_LE(v.y, 2.f);
  }
  // The border's edges: 8 at the start, doubled by each level.
  std::map<std::pair<uint32_t, uint32_t>, int> undirected;
  for (size_t i = 0; i < m.indices.size(); i += 3)
    for (size_t k = 0; k < 3; ++k) {
      const uint32_t a = m.indices[i + k], b = m.indices[i + (k + 1) % 3];
      ++undirected[{std::min(a, b), std::max(a, b)}];
    }
  int border = 0;
  for (const auto& e : undirected) border += e.second == 1;
  EXPECT_EQ(border, 8 * 8);
  for (const Vec3& n : m.normals) EXPECT_EQ(n.z, 1.f);
}

TEST(LoopSubdivision, BadInputIsAnError) {
  std::vector<Vec3> p;
  std::vector<uint32_t> idx;
  icosahedron(&p, &idx);
  EXPECT_THROW(loop_subdivide(p, {0, 1, 12}, 1), Error);                   // index out of range
  EXPECT_THROW(loop_subdivide(p, {}, 1), Error);                           // no triangle
  EXPECT_THROW(loop_subdivide(p, idx, -1), Error);                         // negative levels
  EXPECT_THROW(loop_subdivide(p, idx, 12), Error);                         // 20 x 4^12 triangles: too many
  EXPECT_THROW(loop_subdivide(p, {0, 1, 2, 0, 1, 3, 0, 1, 4}, 1), Error);  // an edge of three triangles
  EXPECT_NO_THROW(loop_subdivide(p, idx, 0));                              // the limit surface only
}

}  // namespace
}  // namespace pathspace
