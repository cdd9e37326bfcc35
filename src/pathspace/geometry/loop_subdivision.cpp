#include "pathspace/geometry/loop_subdivision.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "pathspace/base/error.h"

namespace pathspace {

namespace {

// Positions in double precision while subdividing: levels of averaging stay exact to float.
struct Point {
  double x = 0, y = 0, z = 0;
  Point& operator+=(const Point& o) {
    x += o.x, y += o.y, z += o.z;
    return *this;
  }
};
Point operator*(double s, const Point& p) { return {s * p.x, s * p.y, s * p.z}; }
Point operator+(const Point& a, const Point& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }

uint64_t edge_key(uint32_t a, uint32_t b) { return a < b ? uint64_t(a) << 32 | b : uint64_t(b) << 32 | a; }
uint32_t key_low(uint64_t k) { return uint32_t(k >> 32); }
uint32_t key_high(uint64_t k) { return uint32_t(k & 0xffffffffu); }

// The edges of a triangle mesh, sorted by key, with their one or two opposite vertices, and each
// vertex's neighbours (all, and those across boundary edges).
struct Topology {
  std::vector<uint64_t> keys;
  std::vector<std::array<uint32_t, 2>> opposite;
  std::vector<uint8_t> triangles;  // per edge: 1 (boundary) or 2
  std::vector<std::vector<uint32_t>> neighbours, boundary_neighbours;

  Topology(size_t vertices, const std::vector<uint32_t>& tri) : neighbours(vertices), boundary_neighbours(vertices) {
    std::vector<std::pair<uint64_t, uint32_t>> half(tri.size());
    for (size_t t = 0; t < tri.size(); t += 3)
      for (size_t k = 0; k < 3; ++k) half[t + k] = {edge_key(tri[t + k], tri[t + (k + 1) % 3]), tri[t + (k + 2) % 3]};
    std::sort(half.begin(), half.end());
    for (size_t i = 0; i < half.size();) {
      size_t j = i;
      while (j < half.size() && half[j].first == half[i].first) ++j;
      if (j - i > 2) throw Error("an edge is shared by " + std::to_string(j - i) + " triangles (a non-manifold mesh)");
      keys.push_back(half[i].first);
      opposite.push_back({half[i].second, half[j - 1].second});
      triangles.push_back(uint8_t(j - i));
      i = j;
    }
    for (size_t e = 0; e < keys.size(); ++e) {
      const uint32_t a = key_low(keys[e]), b = key_high(keys[e]);
      neighbours[a].push_back(b);
      neighbours[b].push_back(a);
      if (triangles[e] == 1) {
        boundary_neighbours[a].push_back(b);
        boundary_neighbours[b].push_back(a);
      }
    }
  }

  uint32_t edge(uint32_t a, uint32_t b) const {
    return uint32_t(std::lower_bound(keys.begin(), keys.end(), edge_key(a, b)) - keys.begin());
  }
};

double warren_beta(size_t valence) { return valence == 3 ? 3.0 / 16.0 : 3.0 / (8.0 * double(valence)); }

Point sum_of(const std::vector<Point>& p, const std::vector<uint32_t>& which) {
  Point s;
  for (const uint32_t i : which) s += p[i];
  return s;
}

// The even (old) vertex's new position; `limit` picks the limit masks instead of one level's.
Point even_vertex(const std::vector<Point>& p, const Topology& t, uint32_t v, bool limit) {
  const std::vector<uint32_t>& ring = t.neighbours[v];
  const std::vector<uint32_t>& border = t.boundary_neighbours[v];
  if (border.empty() && ring.size() >= 3) {
    const double n = double(ring.size()), beta = warren_beta(ring.size());
    const double w = limit ? 1.0 / (n + 3.0 / (8.0 * beta)) : beta;
    return (1.0 - n * w) * p[v] + w * sum_of(p, ring);
  }
  if (border.size() == 2) return limit ? (2.0 / 3.0) * p[v] + (1.0 / 6.0) * sum_of(p, border) : 0.75 * p[v] + 0.125 * sum_of(p, border);
  return p[v];  // a corner where fans touch, or an isolated vertex
}

// One level: 4 triangles for each.
void subdivide_once(std::vector<Point>* p, std::vector<uint32_t>* tri) {
  const Topology t(p->size(), *tri);
  const uint32_t old = uint32_t(p->size());
  std::vector<Point> next(old + t.keys.size());
  for (uint32_t v = 0; v < old; ++v) next[v] = even_vertex(*p, t, v, false);
  for (size_t e = 0; e < t.keys.size(); ++e) {
    const Point& a = (*p)[key_low(t.keys[e])];
    const Point& b = (*p)[key_high(t.keys[e])];
    next[old + e] = t.triangles[e] == 2 ? 0.375 * (a + b) + 0.125 * ((*p)[t.opposite[e][0]] + (*p)[t.opposite[e][1]]) : 0.5 * (a + b);
  }
  std::vector<uint32_t> out;
  out.reserve(tri->size() * 4);
  for (size_t i = 0; i < tri->size(); i += 3) {
    const uint32_t v0 = (*tri)[i], v1 = (*tri)[i + 1], v2 = (*tri)[i + 2];
    const uint32_t m01 = old + t.edge(v0, v1), m12 = old + t.edge(v1, v2), m20 = old + t.edge(v2, v0);
    out.insert(out.end(), {v0, m01, m20, v1, m12, m01, v2, m20, m12, m01, m12, m20});
  }
  *p = std::move(next);
  *tri = std::move(out);
}

}  // namespace

SubdividedMesh loop_subdivide(const std::vector<Vec3>& positions, const std::vector<uint32_t>& indices, int levels) {
  if (levels < 0) throw Error("subdivision levels must be >= 0, not " + std::to_string(levels));
  if (indices.empty() || indices.size() % 3) throw Error("needs triangles (indices, a multiple of 3)");
  for (const uint32_t i : indices)
    if (i >= positions.size())
      throw Error("index " + std::to_string(i) + " out of range (" + std::to_string(positions.size()) + " vertices)");
  const uint64_t triangles = indices.size() / 3;
  if (levels > 13 || (triangles << (2 * levels)) > kMaxSubdividedTriangles)
    throw Error(std::to_string(levels) + " levels of " + std::to_string(triangles) + " triangles exceed " +
                std::to_string(kMaxSubdividedTriangles) + " triangles");
  std::vector<Point> p(positions.size());
  for (size_t i = 0; i < p.size(); ++i) p[i] = {positions[i].x, positions[i].y, positions[i].z};
  std::vector<uint32_t> tri = indices;
  for (int l = 0; l < levels; ++l) subdivide_once(&p, &tri);
  // Push to the limit surface.
  const Topology t(p.size(), tri);
  std::vector<Point> limit(p.size());
  for (uint32_t v = 0; v < p.size(); ++v) limit[v] = even_vertex(p, t, v, true);

  SubdividedMesh m;
  m.positions.resize(limit.size());
  for (size_t i = 0; i < limit.size(); ++i) m.positions[i] = Vec3(float(limit[i].x), float(limit[i].y), float(limit[i].z));
  std::vector<Point> n(limit.size());
  for (size_t i = 0; i < tri.size(); i += 3) {
    const Point& a = limit[tri[i]];
    const Point& b = limit[tri[i + 1]];
    const Point& c = limit[tri[i + 2]];
    const Point u{b.x - a.x, b.y - a.y, b.z - a.z}, w{c.x - a.x, c.y - a.y, c.z - a.z};
    const Point face{u.y * w.z - u.z * w.y, u.z * w.x - u.x * w.z, u.x * w.y - u.y * w.x};  // twice the area, oriented
    for (size_t k = 0; k < 3; ++k) n[tri[i + k]] += face;
  }
  m.normals.resize(n.size());
  for (size_t i = 0; i < n.size(); ++i) {
    const double len = std::sqrt(n[i].x * n[i].x + n[i].y * n[i].y + n[i].z * n[i].z);
    if (!(len > 0.0) || !std::isfinite(len)) {  // a degenerate fan: no shading normals for this mesh
      m.normals.clear();
      break;
    }
    m.normals[i] = Vec3(float(n[i].x / len), float(n[i].y / len), float(n[i].z / len));
  }
  m.indices = std::move(tri);
  return m;
}

}  // namespace pathspace
