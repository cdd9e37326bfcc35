// Mitsuba shape tessellation and placement (see mitsuba_shapes.h). Local shapes follow Mitsuba's
// definitions: rectangle [-1,1]^2 at z = 0 facing +z, cube [-1,1]^3 facing out, disk of radius 1 at
// z = 0 facing +z, sphere of `radius` around `center`. Their uvs are Mitsuba's, stored with
// v flipped (v = 1 - v_mitsuba: Mitsuba's v = 0 is an image's top row, pathspace's its bottom row;
// see mitsuba_textures.h), so a bitmap lands where Mitsuba puts it.
#include "pathspace/io/mitsuba/mitsuba_shapes.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "pathspace/geometry/sphere_tessellation.h"
#include "pathspace/geometry/vertex_normals.h"
#include "pathspace/io/obj_loader.h"
#include "pathspace/io/pbrt/pbrt_animated_transform.h"
#include "pathspace/io/ply_reader.h"

namespace pathspace::mitsuba {

namespace {

constexpr int kDiskSegments = 64;
constexpr int kSphereSegments = 64;  // ellipsoids and moving spheres only; other spheres stay analytic

struct LocalMesh {
  std::vector<Vec3> positions;
  std::vector<uint32_t> indices;
  std::vector<Point2> uvs;  // empty or one per position, pathspace convention (v up)
  std::vector<Vec3> normals;  // empty (flat shading) or one outward shading normal per position (add_normals)
};

Point2 from_mitsuba_uv(float u, float v) { return {u, 1.f - v}; }

// The shape's to_world at shutter open and close; `moving` when they differ (motion blur).
struct ShapeTransform {
  Mat4 open, close;
  bool moving = false;
};

// Appends the mesh transformed by m (its vertices at shutter close by m.close when it moves). `flip`
// swaps the winding (analytic shapes under a mirroring transform, flip_normals). Zero-area emitting
// triangles are dropped: they cannot be sampled.
// Shading normals for the vertices the next add_mesh adds: the inverse transpose of to_world (which
// keeps them outward under a mirroring transform too), at shutter close as well when the shape moves;
// inward with flip_normals.
void add_normals(const std::vector<Vec3>& normals, const ShapeTransform& st, bool inward, Scene* s) {
  Mat4 inv_open, inv_close;
  if (!st.open.inverse(&inv_open) || !st.close.inverse(&inv_close)) return;  // a flattened shape: flat shading
  auto world = [&](const Mat4& inv, std::vector<Vec3>* out) {
    for (const Vec3& n : normals) {
      const Vec3 w = Mat4::normal(inv, n);
      const float len = length(w);
      out->push_back(len > 0.f && all_finite(w) ? w * ((inward ? -1.f : 1.f) / len) : Vec3());
    }
  };
  const size_t base = s->positions.size();
  s->normals.resize(base);  // vertices added before without normals: flat (finalize's padding)
  world(inv_open, &s->normals);
  if (st.moving) {
    for (size_t i = s->normals_end.size(); i < base; ++i) s->normals_end.push_back(s->normals[i]);
    world(inv_close, &s->normals_end);
  }
}

void add_mesh(const LocalMesh& mesh, const ShapeTransform& st, bool flip, uint32_t material, const Rgb& le, const FileLoc& loc,
              Scene* s) {
  const Mat4& m = st.open;
  const uint32_t base = uint32_t(s->positions.size());
  if (!mesh.uvs.empty()) {
    s->uvs.resize(base);  // vertices added before without uvs get (0, 0) here
    s->uvs.insert(s->uvs.end(), mesh.uvs.begin(), mesh.uvs.end());
  }
  for (const Vec3& p : mesh.positions) {
    const Vec3 q = m.point(p);
    if (!all_finite(q)) throw Error(loc, "shape vertex is NaN or infinite after to_world");
    s->positions.push_back(q);
  }
  if (st.moving) {  // the vertices at shutter close; the static ones before them stand still
    for (size_t i = s->positions_end.size(); i < base; ++i) s->positions_end.push_back(s->positions[i]);
    for (const Vec3& p : mesh.positions) {
      const Vec3 q = st.close.point(p);
      if (!all_finite(q)) throw Error(loc, "shape vertex is NaN or infinite after to_world at shutter close");
      s->positions_end.push_back(q);
    }
  }
  for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    uint32_t v[3] = {base + mesh.indices[t], base + mesh.indices[t + 1], base + mesh.indices[t + 2]};
    for (uint32_t i : v)
      if (i >= s->positions.size()) throw Error(loc, "mesh index out of range");
    if (flip) std::swap(v[1], v[2]);
    Triangle tri{{v[0], v[1], v[2]}, material, kNoLight};
    if (!is_black(le)) {
      const Vec3 ng = cross(s->positions[v[1]] - s->positions[v[0]], s->positions[v[2]] - s->positions[v[0]]);
      if (!(length(ng) > 0.f)) continue;
      Light l;
      l.type = LightType::area_triangle;
      l.shape = uint32_t(s->triangles.size());
      l.value = le;
      tri.light = int32_t(s->lights.size());
      s->lights.push_back(l);
    }
    s->triangles.push_back(tri);
  }
}

// Mitsuba's rectangle: uv = ((x + 1) / 2, (y + 1) / 2).
LocalMesh rectangle() {
  LocalMesh m{{Vec3(-1, -1, 0), Vec3(1, -1, 0), Vec3(1, 1, 0), Vec3(-1, 1, 0)}, {0, 1, 2, 2, 3, 0}, {}, {}};
  for (const Vec3& p : m.positions) m.uvs.push_back(from_mitsuba_uv(0.5f * (p.x + 1.f), 0.5f * (p.y + 1.f)));
  return m;
}

// Mitsuba's cube: each face maps onto [0, 1]^2. Per face the corners c0..c3 (counter-clockwise seen
// from outside) carry Mitsuba's uvs (0, 1), (1, 1), (1, 0), (0, 0); the face's edge c0 -> c1 is
// Mitsuba's u axis.
LocalMesh cube() {
  // Corner signs (x, y, z) of the faces -y, +y, +x, +z, -x, -z in Mitsuba's order.
  const int corners[6][4][3] = {{{1, -1, -1}, {1, -1, 1}, {-1, -1, 1}, {-1, -1, -1}},
                                {{1, 1, -1}, {-1, 1, -1}, {-1, 1, 1}, {1, 1, 1}},
                                {{1, -1, -1}, {1, 1, -1}, {1, 1, 1}, {1, -1, 1}},
                                {{1, -1, 1}, {1, 1, 1}, {-1, 1, 1}, {-1, -1, 1}},
                                {{-1, -1, 1}, {-1, 1, 1}, {-1, 1, -1}, {-1, -1, -1}},
                                {{1, 1, -1}, {1, -1, -1}, {-1, -1, -1}, {-1, 1, -1}}};
  const float uv[4][2] = {{0, 1}, {1, 1}, {1, 0}, {0, 0}};
  LocalMesh m;
  for (const auto& face : corners) {
    const uint32_t base = uint32_t(m.positions.size());
    for (int i = 0; i < 4; ++i) {
      m.positions.push_back(Vec3(float(face[i][0]), float(face[i][1]), float(face[i][2])));
      m.uvs.push_back(from_mitsuba_uv(uv[i][0], uv[i][1]));
    }
    for (uint32_t i : {0u, 1u, 2u, 3u, 0u, 2u}) m.indices.push_back(base + i);
  }
  return m;
}

// Mitsuba's disk uv is (radius, angle / 2 pi). Each fan triangle has its own three vertices: the
// centre takes the triangle's mid angle and the rim vertex at angle 2 pi has v = 1 (no seam).
LocalMesh disk() {
  // The polygon's radius is enlarged so that its area equals the disk's (emitted power unchanged).
  const double n = kDiskSegments, r = std::sqrt(M_PI / (0.5 * n * std::sin(2.0 * M_PI / n)));
  LocalMesh m;
  for (int i = 0; i < kDiskSegments; ++i) {
    const uint32_t base = uint32_t(m.positions.size());
    const double phi0 = 2.0 * M_PI * i / n, phi1 = 2.0 * M_PI * (i + 1) / n;
    m.positions.push_back(Vec3(0, 0, 0));
    m.positions.push_back(Vec3(float(r * std::cos(phi0)), float(r * std::sin(phi0)), 0.f));
    m.positions.push_back(Vec3(float(r * std::cos(phi1)), float(r * std::sin(phi1)), 0.f));
    m.uvs.push_back(from_mitsuba_uv(0.f, float((i + 0.5) / n)));
    m.uvs.push_back(from_mitsuba_uv(1.f, float(i / n)));
    m.uvs.push_back(from_mitsuba_uv(1.f, float((i + 1) / n)));
    m.indices.insert(m.indices.end(), {base, base + 1, base + 2});
  }
  return m;
}

// Mitsuba's sphere uv is (phi / 2 pi, theta / pi) with theta from +z: the tessellation's v turned
// over, which from_mitsuba_uv turns back.
LocalMesh uv_sphere() {
  TessellatedSphere t = tessellate_unit_sphere(kSphereSegments);
  LocalMesh m;
  for (const Point2& p : t.params) m.uvs.push_back(from_mitsuba_uv(p.x, 1.f - p.y));
  m.normals = t.points;
  m.positions = std::move(t.points);
  m.indices = std::move(t.indices);
  return m;
}

std::filesystem::path resolve(const Object& o, const std::string& folder) {
  const std::string file = o.get_string("filename", "");
  if (file.empty()) throw Error(o.loc(), o.title() + " needs a filename");
  return o.doc().resolve_file(file, folder);
}

LocalMesh mesh_file(const Object& o, const std::string& folder, LoadWarnings* w) {
  const std::filesystem::path path = resolve(o, folder);
  const bool face_normals = o.get_bool("face_normals", false);
  const bool flip_uv = o.type() == "obj" && o.get_bool("flip_tex_coords", true);
  LocalMesh m;
  try {
    // Mitsuba reads PLY uvs as they are and flips OBJ ones unless flip_tex_coords is false.
    if (o.type() == "ply") {
      PlyMesh ply = read_ply(path.string());
      m.positions = std::move(ply.positions);
      if (ply.normals.size() == m.positions.size()) m.normals = std::move(ply.normals);
      m.indices = std::move(ply.indices);
      for (const auto& uv : ply.uvs) m.uvs.push_back(from_mitsuba_uv(uv[0], uv[1]));
    } else {
      Scene tmp;  // the OBJ's own materials and emitters are replaced by the XML's
      load_obj_into(path.string(), w, &tmp);
      m.positions = std::move(tmp.positions);
      for (const Triangle& t : tmp.triangles) m.indices.insert(m.indices.end(), {t.v[0], t.v[1], t.v[2]});
      if (!tmp.uvs.empty()) {
        tmp.uvs.resize(m.positions.size());
        for (const Point2& uv : tmp.uvs) m.uvs.push_back(flip_uv ? uv : Point2{uv.x, 1.f - uv.y});
      }
      // The file's vn where it gives them; a vertex without one gets a computed normal below.
      if (!tmp.normals.empty()) tmp.normals.resize(m.positions.size()), m.normals = std::move(tmp.normals);
    }
  } catch (const Error& e) {
    throw Error(o.loc(), o.title() + ": " + e.what());
  }
  // As Mitsuba 3: the file's vertex normals, else smooth ones computed from the faces; face_normals
  // discards both (flat shading).
  if (face_normals) {
    m.normals.clear();
  } else if (m.normals.size() != m.positions.size() ||
             std::any_of(m.normals.begin(), m.normals.end(), [](const Vec3& n) { return !(dot(n, n) > 0.f); })) {
    const std::vector<Vec3> computed = angle_weighted_vertex_normals(m.positions, m.indices);
    m.normals.resize(m.positions.size());
    for (size_t i = 0; i < m.normals.size(); ++i)
      if (!(dot(m.normals[i], m.normals[i]) > 0.f)) m.normals[i] = computed[i];
  }
  o.ignore({"face_normals", "max_smooth_angle", "vertex_count", "face_count"});
  return m;
}

// to_world at the shutter's ends, with warnings where two time steps cannot follow the animation.
ShapeTransform shape_transform(const Object& o, const Shutter& shutter, LoadWarnings* w) {
  const Object::TransformKeys keys = o.get_transform_keys("to_world");
  ShapeTransform st;
  st.open = keys.at(shutter.open, o.loc());
  st.close = keys.at(shutter.close, o.loc());
  st.moving = !(st.open == st.close);
  if (!st.moving) return st;
  for (const double t : keys.times)
    if (t > shutter.open && t < shutter.close) {
      w->add(o.loc(), o.title() + ": an animation key lies inside the shutter interval; vertices move on straight lines from "
                      "shutter open to close, past it");
      break;
    }
  const double degrees = pbrt::rotation_between_degrees(st.open, st.close);
  if (degrees > pbrt::kMaxLinearRotationDegrees)
    w->add(o.loc(), o.title() + ": the shape turns " + std::to_string(int(std::lround(degrees))) +
                        " degrees while the shutter is open; its vertices move on straight lines, not on arcs");
  return st;
}

}  // namespace

InstanceTransform instance_transform(const Object& instance, const Shutter& shutter, LoadWarnings* w) {
  const ShapeTransform st = shape_transform(instance, shutter, w);
  return {st.open, st.close};
}

void add_shape(const Object& o, uint32_t material, const Rgb& le, const std::string& folder, const Shutter& shutter, LoadWarnings* w,
               Scene* scene, const InstanceTransform& instance) {
  const std::string& t = o.type();
  ShapeTransform st = shape_transform(o, shutter, w);
  st.open = instance.open * st.open;
  st.close = instance.close * st.close;
  st.moving = !(st.open == st.close);
  const Mat4& m = st.open;
  const bool flip_normals = o.get_bool("flip_normals", false);
  // Analytic shapes transform their normal with the inverse transpose, so a mirroring to_world
  // turns the winding against it; meshes keep their world-space winding (Mitsuba's convention).
  const bool mirrored = m.det3() < 0.0;
  if (t == "rectangle" || t == "cube") {
    add_mesh(t == "rectangle" ? rectangle() : cube(), st, mirrored != flip_normals, material, le, o.loc(), scene);
  } else if (t == "disk") {
    add_mesh(disk(), st, mirrored != flip_normals, material, le, o.loc(), scene);
  } else if (t == "sphere") {
    const Vec3 center = o.get_vector("center", Vec3());
    const float radius = float(o.get_float("radius", 1.0));
    if (!(radius > 0.f) || !all_finite(center)) throw Error(o.loc(), "sphere radius must be > 0");
    const Mat4 local = Mat4::translate(center.x, center.y, center.z) * Mat4::scale(radius, radius, radius);
    const Mat4 full = m * local;
    const Vec3 c0 = full.vector(Vec3(1, 0, 0)), c1 = full.vector(Vec3(0, 1, 0)), c2 = full.vector(Vec3(0, 0, 1));
    const float s = length(c0);
    const bool similarity = std::fabs(length(c1) - s) <= 1e-4f * s && std::fabs(length(c2) - s) <= 1e-4f * s &&
                            abs_dot(c0, c1) <= 1e-4f * s * s && abs_dot(c0, c2) <= 1e-4f * s * s && abs_dot(c1, c2) <= 1e-4f * s * s;
    if (similarity && s > 0.f && std::isfinite(s) && !st.moving) {
      scene->add_sphere(full.point(Vec3()), s, material, le, flip_normals);
    } else {
      const LocalMesh mesh = uv_sphere();
      w->add(o.loc(), std::string(st.moving ? "moving sphere" : "sphere under a non-uniform scale or shear") + " triangulated (" +
                          std::to_string(mesh.indices.size() / 3) + " triangles)");
      const ShapeTransform sphere{full, st.close * local, st.moving};
      add_normals(mesh.normals, sphere, flip_normals, scene);
      add_mesh(mesh, sphere, mirrored != flip_normals, material, le, o.loc(), scene);
    }
  } else if (t == "obj" || t == "ply") {
    const LocalMesh mesh = mesh_file(o, folder, w);
    if (!mesh.normals.empty()) add_normals(mesh.normals, st, flip_normals, scene);
    add_mesh(mesh, st, flip_normals, material, le, o.loc(), scene);
  } else {
    w->add(o.loc(), "shape type '" + t + "' not supported; skipped");
    o.ignore_all();
  }
}

}  // namespace pathspace::mitsuba
