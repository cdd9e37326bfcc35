#include "pathspace/io/pbrt/pbrt_tessellated_shapes.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "pathspace/base/error.h"
#include "pathspace/geometry/loop_subdivision.h"
#include "pathspace/geometry/sphere_tessellation.h"

namespace pathspace::pbrt {

ObjectMesh disk_mesh(const Statement& st, LoadWarnings* warnings) {
  const double radius = st.get_float("radius", 1.0), inner = st.get_float("innerradius", 0.0);
  const double height = st.get_float("height", 0.0), phimax_deg = st.get_float("phimax", 360.0);
  if (!(radius > 0.0) || !(inner >= 0.0) || !(inner < radius)) throw Error(st.loc, "disk: need 0 <= innerradius < radius");
  if (!(phimax_deg > 0.0) || phimax_deg > 360.0) throw Error(st.loc, "disk: phimax must be in (0, 360]");
  const double phimax = phimax_deg * M_PI / 180.0;
  const int segments = std::max(3, int(std::ceil(kDiskSegments * phimax_deg / 360.0)));
  // Vertices on a slightly larger circle so that the polygon's area equals the disk's: an area light
  // on a disk then emits the same power as pbrt's.
  const double dphi = phimax / segments;
  const double grow = std::sqrt(dphi / std::sin(dphi));
  warnings->add(st.loc, "disk tessellated into " + std::to_string(segments * (inner > 0.0 ? 2 : 1)) +
                            " triangles (area preserved)");
  ObjectMesh m;
  for (int ring = 0; ring < 2; ++ring) {
    const double r = (ring == 0 ? radius : inner) * grow;
    for (int i = 0; i <= segments; ++i) {
      const double phi = dphi * i;
      m.positions.push_back(Vec3(float(r * std::cos(phi)), float(r * std::sin(phi)), float(height)));
      m.normals.push_back(Vec3(0.f, 0.f, 1.f));  // pbrt's disk faces +z
      m.uvs.push_back({float(phi / phimax), ring == 0 ? 0.f : 1.f});  // pbrt: v = (radius - r) / (radius - inner)
    }
  }
  const uint32_t outer = 0, in = uint32_t(segments + 1);
  for (uint32_t i = 0; i < uint32_t(segments); ++i) {
    if (inner > 0.0) {
      m.indices.insert(m.indices.end(), {outer + i, outer + i + 1, in + i + 1, outer + i, in + i + 1, in + i});
    } else {
      m.indices.insert(m.indices.end(), {outer + i, outer + i + 1, in + i});  // `in + i` is the centre
    }
  }
  return m;
}

ObjectMesh bilinear_mesh(const Statement& st, LoadWarnings* warnings) {
  const std::vector<double> p = st.get_numbers("P");
  std::vector<double> idx = st.get_numbers("indices");
  const std::vector<double> n = st.get_numbers("N");
  const std::vector<double> uv = st.get_numbers("uv");
  if (p.empty() || p.size() % 3) throw Error(st.loc, "bilinearmesh needs \"point3 P\" with a multiple of 3 values");
  const size_t verts = p.size() / 3;
  if (idx.empty() && verts == 4) idx = {0, 1, 2, 3};
  if (idx.empty() || idx.size() % 4) throw Error(st.loc, "bilinearmesh needs \"integer indices\" with a multiple of 4 values");
  if (!n.empty() && n.size() != p.size()) throw Error(st.loc, "bilinearmesh: N must have one normal per vertex");
  if (!uv.empty() && uv.size() != verts * 2) throw Error(st.loc, "bilinearmesh: uv must have one point2 per vertex");
  ObjectMesh m;
  for (size_t i = 0; i < verts; ++i) m.positions.push_back(Vec3(float(p[3 * i]), float(p[3 * i + 1]), float(p[3 * i + 2])));
  for (size_t i = 0; i < n.size() / 3; ++i) m.normals.push_back(Vec3(float(n[3 * i]), float(n[3 * i + 1]), float(n[3 * i + 2])));
  for (size_t i = 0; i < uv.size() / 2; ++i) m.uvs.push_back({float(uv[2 * i]), float(uv[2 * i + 1])});
  bool curved = false;
  for (size_t q = 0; q < idx.size(); q += 4) {
    uint32_t v[4];
    for (int k = 0; k < 4; ++k) {
      if (idx[q + size_t(k)] < 0 || idx[q + size_t(k)] >= double(verts))
        throw Error(st.find("indices")->loc, "index " + std::to_string(int64_t(idx[q + size_t(k)])) + " out of range (" +
                                                 std::to_string(verts) + " vertices)");
      v[k] = uint32_t(idx[q + size_t(k)]);
    }
    // pbrt's patch corners are p00, p10, p01, p11: the triangles (p00, p10, p11) and (p00, p11, p01).
    m.indices.insert(m.indices.end(), {v[0], v[1], v[3], v[0], v[3], v[2]});
    const Vec3 a = m.positions[v[0]], b = m.positions[v[1]], c = m.positions[v[2]], d = m.positions[v[3]];
    const Vec3 nrm = cross(b - a, c - a);
    const float scale = std::max({length(b - a), length(c - a), 1e-30f});
    if (length(nrm) > 0.f && std::fabs(dot(normalize(nrm), d - a)) > 1e-4f * scale) curved = true;
  }
  if (curved) warnings->add(st.loc, "bilinearmesh: non-planar patches approximated by two triangles each");
  return m;
}

ObjectMesh loop_subdivision_mesh(const Statement& st) {
  const std::vector<double> p = st.get_numbers("P");
  const std::vector<double> idx = st.get_numbers("indices");
  const int levels = st.get_int("levels", 3);
  if (p.empty() || p.size() % 3) throw Error(st.loc, "loopsubdiv needs \"point3 P\" with a multiple of 3 values");
  if (idx.empty() || idx.size() % 3) throw Error(st.loc, "loopsubdiv needs \"integer indices\" with a multiple of 3 values");
  std::vector<Vec3> positions(p.size() / 3);
  for (size_t i = 0; i < positions.size(); ++i) positions[i] = Vec3(float(p[3 * i]), float(p[3 * i + 1]), float(p[3 * i + 2]));
  std::vector<uint32_t> indices(idx.size());
  for (size_t i = 0; i < idx.size(); ++i) {
    if (idx[i] < 0 || idx[i] >= double(positions.size()))
      throw Error(st.find("indices")->loc, "index " + std::to_string(int64_t(idx[i])) + " out of range (" +
                                               std::to_string(positions.size()) + " vertices)");
    indices[i] = uint32_t(idx[i]);
  }
  SubdividedMesh s;
  try {
    s = loop_subdivide(positions, indices, levels);
  } catch (const Error& e) {
    throw Error(st.loc, std::string("loopsubdiv: ") + e.what());
  }
  ObjectMesh m;
  m.positions = std::move(s.positions);
  m.normals = std::move(s.normals);
  m.indices = std::move(s.indices);
  return m;
}

ObjectMesh sphere_mesh(float radius) {
  // pbrt-v4's sphere uv: u = phi / 2 pi, v = 0 at the -z pole: the tessellation's parameters as they are.
  TessellatedSphere t = tessellate_unit_sphere(kSphereSegments);
  ObjectMesh m;
  for (size_t i = 0; i < t.points.size(); ++i) {
    m.positions.push_back(t.points[i] * radius);
    m.uvs.push_back({t.params[i].x, t.params[i].y});
  }
  m.normals = std::move(t.points);
  m.indices = std::move(t.indices);
  return m;
}

}  // namespace pathspace::pbrt
