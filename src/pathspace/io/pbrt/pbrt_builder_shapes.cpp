// The pbrt-v4 scene builder's shapes (pbrt_builder.h): triangle, PLY, bilinear and subdivision
// meshes, disks and spheres, moving shapes, area lights and their "power", cutout materials and
// object instances.
#include "pathspace/io/pbrt/pbrt_builder.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>

#include "pathspace/io/pbrt/pbrt_paths.h"
#include "pathspace/io/pbrt/pbrt_tessellated_shapes.h"
#include "pathspace/io/ply_reader.h"

namespace pathspace::pbrt {

void SceneBuilder::instance(const Statement& st) {
  if (object_depth_ > 0) throw Error(st.loc, "ObjectInstance inside ObjectBegin");
  const auto it = objects_.find(st.strings[0]);
  if (it == objects_.end()) throw Error(st.loc, "object \"" + st.strings[0] + "\" is not defined");
  const bool first_use = instanced_.insert(st.strings[0]).second;
  const GraphicsState saved = gs_;
  for (const auto& [shape_st, shape_gs] : it->second) {
    Statement copy = shape_st;
    for (const Param& p : copy.params) p.used = false;
    gs_ = shape_gs;
    gs_.ctm = saved.ctm * shape_gs.ctm;
    gs_.ctm_end = saved.ctm_end * shape_gs.ctm_end;
    shape(copy);
    if (first_use)
      for (const Param& p : copy.params)
        if (!p.used) warn(p.loc, copy.title() + ": parameter \"" + p.type + " " + p.name + "\" is not supported; ignored");
  }
  gs_ = saved;
}

void SceneBuilder::shape(const Statement& st) {
  if (object_depth_ > 0) {  // kept for ObjectInstance, with the graphics state it was defined in
    objects_[current_object_].push_back({st, gs_});
    mark_all(st);
    return;
  }
  const SceneCounts before = SceneCounts::of(scene_);
  shape_geometry(st);
  media_.bind(gs_.media, before, SceneCounts::of(scene_));
  if (const auto it = interior_media_.find(gs_.material); it != interior_media_.end())
    media_.bind_interior(gs_.media, it->second, before, SceneCounts::of(scene_));
}

void SceneBuilder::shape_geometry(const Statement& st) {
  const std::string& type = st.strings[0];
  st.ignore({"faceIndices"});
  if (type == "trianglemesh") {
    const std::vector<double> p = st.get_numbers("P");
    std::vector<double> idx = st.get_numbers("indices");
    const std::vector<double> nrm = st.get_numbers("N");
    const std::vector<double> uv = st.get_numbers(st.find("uv") ? "uv" : "st");
    if (p.empty() || p.size() % 3) throw Error(st.loc, "trianglemesh needs \"point3 P\" with a multiple of 3 values");
    if (idx.empty() && p.size() == 9) idx = {0, 1, 2};
    if (idx.empty() || idx.size() % 3) throw Error(st.loc, "trianglemesh needs \"integer indices\" with a multiple of 3 values");
    if (!nrm.empty() && nrm.size() != p.size()) throw Error(st.loc, "trianglemesh: N must have one normal per vertex");
    if (!uv.empty() && uv.size() != p.size() / 3 * 2) throw Error(st.loc, "trianglemesh: uv must have one point2 per vertex");
    std::vector<Vec3> pos(p.size() / 3), normals(nrm.size() / 3);
    std::vector<std::array<float, 2>> uvs(uv.size() / 2);
    for (size_t i = 0; i < uvs.size(); ++i) uvs[i] = {float(uv[2 * i]), float(uv[2 * i + 1])};
    for (size_t i = 0; i < pos.size(); ++i) pos[i] = vec_at(p, i);
    for (size_t i = 0; i < normals.size(); ++i) normals[i] = vec_at(nrm, i);
    std::vector<uint32_t> tri(idx.size());
    for (size_t i = 0; i < idx.size(); ++i) {
      if (idx[i] < 0 || idx[i] >= double(pos.size()))
        throw Error(st.find("indices")->loc, "index " + std::to_string(int64_t(idx[i])) + " out of range (" + std::to_string(pos.size()) + " vertices)");
      tri[i] = uint32_t(idx[i]);
    }
    add_mesh(st, pos, normals, uvs, tri);
  } else if (type == "plymesh") {
    const std::string file = st.get_string("filename", "");
    const std::filesystem::path path = resolve_scene_file(file, folder_of(st), main_folder_);
    std::error_code ec;
    if (!file.empty() && !std::filesystem::exists(path, ec)) {  // listed with the other missing files at the end
      missing_.add(st.find("filename")->loc, "PLY mesh", file);
      return;
    }
    PlyMesh mesh;
    try {
      mesh = read_ply(path.string());
    } catch (const Error& e) {
      throw Error(st.loc, "plymesh \"" + file + "\": " + e.what());
    }
    add_mesh(st, mesh.positions, mesh.normals, mesh.uvs, mesh.indices);
  } else if (type == "sphere") {
    sphere(st);
  } else if (type == "disk" || type == "bilinearmesh" || type == "loopsubdiv") {
    const ObjectMesh m = type == "disk"           ? disk_mesh(st, warnings_)
                         : type == "bilinearmesh" ? bilinear_mesh(st, warnings_)
                                                  : loop_subdivision_mesh(st);
    // pbrt-v4 makes a disk one shape, a bilinear mesh one per patch, a subdivision surface one per
    // triangle: what "power" of an area light is emitted by (add_mesh).
    add_mesh(st, m.positions, m.normals, m.uvs, m.indices, type == "disk" ? 0 : type == "bilinearmesh" ? 2 : 1);
  } else {
    warn(st.loc, "Shape \"" + type + "\" is not supported; skipped");
    mark_all(st);
  }
}

uint32_t SceneBuilder::shape_material(const Statement& st) {
  if (gs_.material < 0 && default_material_ < 0)
    default_material_ = int(scene_.add_material(make_material("diffuse", Statement{}, textures_, warnings_)));
  const uint32_t material = uint32_t(gs_.material >= 0 ? gs_.material : default_material_);
  if (!st.find("alpha")) return material;
  int32_t texture = -1;
  const float alpha = float_texture_param(st, "alpha", 1.f, &textures_, warnings_, &texture);
  if (!(alpha >= 0.f && alpha <= 1.f)) throw Error(st.find("alpha")->loc, "\"alpha\" must lie in [0, 1]");
  if (alpha == 1.f && texture < 0) return material;
  const auto key = std::make_tuple(material, alpha, texture);
  const auto it = cutout_materials_.find(key);
  if (it != cutout_materials_.end()) return it->second;
  Material m = scene_.materials[material];
  m.opacity = alpha;
  m.opacity_texture = texture;
  const uint32_t copy = scene_.add_material(m);
  cutout_materials_.emplace(key, copy);
  return copy;
}

Rgb SceneBuilder::emission(const Statement& st, uint32_t material) {
  if (!gs_.area_light) return Rgb();
  const Material& m = scene_.materials[material];
  if (!is_black(m.diffuse) || !is_black(m.glossy) || !is_black(m.specular) || m.type != MaterialType::standard)
    warn(st.loc, "an emissive shape's material is ignored (pathspace emitters do not reflect light)");
  return gs_.area_radiance;
}

Rgb SceneBuilder::shape_radiance(const Rgb& le, double area) const {
  if (!(gs_.area_power > 0.f) || is_black(le)) return le;
  return area > 0.0 ? le * float(gs_.area_power / ((gs_.area_two_sided ? 2.0 : 1.0) * M_PI * area)) : Rgb();
}

void SceneBuilder::add_mesh(const Statement& st, const std::vector<Vec3>& pos, const std::vector<Vec3>& normals,
              const std::vector<std::array<float, 2>>& uvs, const std::vector<uint32_t>& idx, int triangles_per_shape) {
  const uint32_t material = shape_material(st);
  const Rgb le_shape = emission(st, material);
  Mat4 open, close;
  const bool moving = shutter_transforms(st.loc, &open, &close);
  Mat4 inv, inv_close;
  if (!open.inverse(&inv) || !close.inverse(&inv_close)) throw Error(st.loc, "shape transform is singular");
  const bool flip_default = gs_.reverse_orientation != (open.det3() < 0.0);
  const uint32_t base = uint32_t(scene_.positions.size());
  for (const Vec3& p : pos) scene_.positions.push_back(open.point(p));
  if (moving) {  // the vertices at shutter close; the static ones before them stand still
    for (size_t i = scene_.positions_end.size(); i < base; ++i) scene_.positions_end.push_back(scene_.positions[i]);
    for (const Vec3& p : pos) scene_.positions_end.push_back(close.point(p));
  }
  if (uvs.size() == pos.size()) {
    scene_.uvs.resize(base);
    for (const auto& t : uvs) scene_.uvs.push_back(Point2{t[0], t[1]});
  }
  // Each triangle's pbrt shape's area in world space (for "power").
  std::vector<double> shape_area(idx.size() / 3, 0.0);
  if (gs_.area_power > 0.f) {
    const size_t n = shape_area.size(), group = triangles_per_shape > 0 ? size_t(triangles_per_shape) : std::max<size_t>(n, 1);
    for (size_t first = 0; first < n; first += group) {
      double sum = 0.0;
      for (size_t t = first; t < std::min(n, first + group); ++t) {
        const Vec3 a = scene_.positions[base + idx[3 * t]], b = scene_.positions[base + idx[3 * t + 1]], c = scene_.positions[base + idx[3 * t + 2]];
        sum += 0.5 * double(length(cross(b - a, c - a)));
      }
      for (size_t t = first; t < std::min(n, first + group); ++t) shape_area[t] = sum;
    }
  }
  bool smooth = false;
  for (size_t t = 0; t + 2 < idx.size(); t += 3) {
    const Rgb le = shape_radiance(le_shape, shape_area[t / 3]);
    uint32_t v[3] = {base + idx[t], base + idx[t + 1], base + idx[t + 2]};
    const Vec3 ng = cross(scene_.positions[v[1]] - scene_.positions[v[0]], scene_.positions[v[2]] - scene_.positions[v[0]]);
    const float area2 = length(ng);
    bool flip = flip_default;
    if (!normals.empty()) {
      Vec3 ns;
      for (int k = 0; k < 3; ++k) {
        const Vec3 nk = normalize(Mat4::normal(inv, normals[idx[t + size_t(k)]]));
        ns += gs_.reverse_orientation ? -nk : nk;
        if (area2 > 0.f && abs_dot(nk, ng / area2) < 0.999f) smooth = true;
      }
      flip = dot(ns, ng) < 0.f;
    }
    if (flip) std::swap(v[1], v[2]);
    if (!is_black(le) && !(area2 > 0.f)) continue;  // a zero-area emitter cannot be sampled
    Triangle tri{{v[0], v[1], v[2]}, material, kNoLight};
    if (!is_black(le)) {
      Light l;
      l.type = LightType::area_triangle;
      l.shape = uint32_t(scene_.triangles.size());
      l.value = le;
      l.two_sided = gs_.area_two_sided;
      tri.light = int32_t(scene_.lights.size());
      scene_.lights.push_back(l);
    }
    scene_.triangles.push_back(tri);
  }
  if (smooth && normals.size() == pos.size()) {  // flat meshes need no shading normals
    auto world_normal = [&](const Mat4& inverse, const Vec3& n) {
      const Vec3 w = Mat4::normal(inverse, n);
      const float len = length(w);
      return len > 0.f && all_finite(w) ? w * ((gs_.reverse_orientation ? -1.f : 1.f) / len) : Vec3();
    };
    scene_.normals.resize(base);
    for (const Vec3& n : normals) scene_.normals.push_back(world_normal(inv, n));
    if (moving) {
      for (size_t i = scene_.normals_end.size(); i < base; ++i) scene_.normals_end.push_back(scene_.normals[i]);
      for (const Vec3& n : normals) scene_.normals_end.push_back(world_normal(inv_close, n));
    }
  }
}

void SceneBuilder::sphere(const Statement& st) {
  const float radius = float(st.get_float("radius", 1.0));
  const double zmin = st.get_float("zmin", -radius), zmax = st.get_float("zmax", radius), phimax = st.get_float("phimax", 360.0);
  if (zmin > -radius || zmax < radius || phimax < 360.0) warn(st.loc, "partial sphere (zmin/zmax/phimax) rendered as a full sphere");
  Mat4 open, close;
  if (shutter_transforms(st.loc, &open, &close)) {
    // Spheres do not move (scene/motion.h): a moving one becomes a triangle mesh that does.
    if (!(radius > 0.f)) throw Error(st.loc, "sphere radius must be > 0");
    const ObjectMesh m = sphere_mesh(radius);
    warn(st.loc, fmt::format("a moving sphere is rendered as a mesh of {} triangles", m.indices.size() / 3));
    add_mesh(st, m.positions, m.normals, m.uvs, m.indices, 0);
    return;
  }
  // Only similarity transforms keep a sphere a sphere.
  const Vec3 c0 = gs_.ctm.vector(Vec3(1, 0, 0)), c1 = gs_.ctm.vector(Vec3(0, 1, 0)), c2 = gs_.ctm.vector(Vec3(0, 0, 1));
  const float s = length(c0);
  if (std::fabs(length(c1) - s) > 1e-4f * s || std::fabs(length(c2) - s) > 1e-4f * s || abs_dot(c0, c1) > 1e-4f * s * s ||
      abs_dot(c0, c2) > 1e-4f * s * s || abs_dot(c1, c2) > 1e-4f * s * s)
    throw Error(st.loc, "sphere under a non-uniform scale or shear is not supported");
  if (!(radius > 0.f)) throw Error(st.loc, "sphere radius must be > 0");
  const uint32_t material = shape_material(st);
  const double world_radius = double(radius) * double(s);
  const Rgb le = shape_radiance(emission(st, material), 4.0 * M_PI * world_radius * world_radius);
  if (!is_black(le) && gs_.area_two_sided) warn(st.loc, "two-sided emission of a sphere: only the outside emits");
  const bool inward = gs_.reverse_orientation != (gs_.ctm.det3() < 0.0);
  scene_.add_sphere(gs_.ctm.point(Vec3()), radius * s, material, le, inward);
}

}  // namespace pathspace::pbrt
