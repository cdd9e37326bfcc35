// pbrt-v4 media (see pbrt_media.h): parameters and defaults as pbrt-v4's HomogeneousMedium,
// GridMedium ("uniformgrid") and RGBGridMedium: sigma_a = sigma_s = 1 and scale 1 unless given, g 0,
// grid samples cell-centred over the box p0..p1 (default the unit cube) in the medium's space.
#include "pathspace/io/pbrt/pbrt_media.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace pathspace::pbrt {

bool world_to_unit_box(const Mat4& world_from_box, const double lo[3], const double hi[3], float out[12]) {
  Mat4 box_from_world;
  if (!world_from_box.inverse(&box_from_world)) return false;
  Mat4 unit;  // box -> [0, 1]^3
  for (int a = 0; a < 3; ++a) {
    const double l = std::min(lo[a], hi[a]), extent = std::fabs(hi[a] - lo[a]);
    if (!(extent > 0.0) || !std::isfinite(extent)) return false;
    unit.m[a][a] = 1.0 / extent;
    unit.m[a][3] = -l / extent;
  }
  const Mat4 m = unit * box_from_world;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 4; ++c) {
      out[r * 4 + c] = float(m.m[r][c]);
      if (!std::isfinite(out[r * 4 + c])) return false;
    }
  return true;
}

void bind_added(const MediumInterface& m, const SceneCounts& before, const SceneCounts& after, SceneMedia* media) {
  if (m.transition) {
    for (size_t t = before.triangles; t < after.triangles; ++t) media->bind_triangle(uint32_t(t), m);
    for (size_t s = before.spheres; s < after.spheres; ++s) media->bind_sphere(uint32_t(s), m);
  }
  if (m.outside != kVacuum)
    for (size_t l = before.lights; l < after.lights; ++l) media->bind_light(uint32_t(l), m.outside);
}

namespace {

// The location of parameter `name` when given, else the statement's.
FileLoc loc_of(const Statement& st, const std::string& name) {
  const Param* p = st.find(name);
  return p ? p->loc : st.loc;
}

Rgb coefficient(const Statement& st, const std::string& name, const TextureTable& textures, LoadWarnings* w) {
  const Rgb c = spectrum_param(st, name, Rgb(1.f), textures, w, SpectrumUse::unbounded);
  for (int i = 0; i < 3; ++i)
    if (!std::isfinite(c[i]) || c[i] < 0.f)
      throw Error(loc_of(st, name), fmt::format("medium \"{}\" must be finite and >= 0 (got {}, {}, {})", name, c.r, c.g, c.b));
  return c;
}

float scale_param(const Statement& st) {
  const double s = st.get_float("scale", 1.0);
  if (!(s >= 0.0) || !std::isfinite(s)) throw Error(loc_of(st, "scale"), fmt::format("medium \"scale\" must be finite and >= 0 (got {})", s));
  return float(s);
}

float g_param(const Statement& st) {
  const double g = st.get_float("g", 0.0);
  if (!(g > -1.0 && g < 1.0)) throw Error(loc_of(st, "g"), fmt::format("medium phase asymmetry \"g\" must lie in (-1, 1) (got {})", g));
  return float(g);
}

Rgb albedo_of(const Rgb& sigma_a, const Rgb& sigma_s) {
  Rgb a;
  for (int c = 0; c < 3; ++c) {
    const float t = sigma_a[c] + sigma_s[c];
    a[c] = t > 0.f ? sigma_s[c] / t : 0.f;
  }
  return a;
}

// nx, ny, nz (pbrt-v4's default 1 each) and the grid's placement: the box p0..p1 under the CTM.
void grid_shape(const Statement& st, const Mat4& ctm, GridMediumDesc* d) {
  int n[3];
  const char* names[3] = {"nx", "ny", "nz"};
  for (int a = 0; a < 3; ++a) {
    n[a] = st.get_int(names[a], 1);
    if (n[a] < 1) throw Error(loc_of(st, names[a]), fmt::format("medium grid: \"{}\" must be >= 1 (got {})", names[a], n[a]));
  }
  d->nx = uint32_t(n[0]), d->ny = uint32_t(n[1]), d->nz = uint32_t(n[2]);
  double corners[2][3] = {{0, 0, 0}, {1, 1, 1}};
  const char* points[2] = {"p0", "p1"};
  for (int k = 0; k < 2; ++k) {
    const std::vector<double> p = st.get_numbers(points[k]);
    if (p.empty()) continue;
    if (p.size() != 3) throw Error(loc_of(st, points[k]), std::string("medium grid: \"") + points[k] + "\" needs one point3");
    std::copy(p.begin(), p.end(), corners[k]);
  }
  if (!world_to_unit_box(ctm, corners[0], corners[1], d->world_to_grid))
    throw Error(st.loc, "medium grid: the box p0..p1 is flat or its transform is singular");
}

// The number of samples nx * ny * nz, checked against the values given (per sample `per` numbers).
void check_count(const Statement& st, const std::string& name, size_t values, size_t per, const GridMediumDesc& d) {
  const uint64_t expected = uint64_t(d.nx) * d.ny * d.nz;
  if (values % per != 0 || values / per != expected)
    throw Error(loc_of(st, name), fmt::format("medium grid \"{}\" has {} values; nx * ny * nz = {} x {} x {} asks for {}", name,
                                              values, d.nx, d.ny, d.nz, expected * per));
}

void check_values(const Statement& st, const std::string& name, const std::vector<double>& v) {
  for (size_t i = 0; i < v.size(); ++i)
    if (!(v[i] >= 0.0) || !std::isfinite(v[i]))
      throw Error(loc_of(st, name), fmt::format("medium grid \"{}\": value {} is {} (must be finite and >= 0)", name, i, v[i]));
}

GridMediumDesc uniform_grid(const Statement& st, const Mat4& ctm, const TextureTable& textures, LoadWarnings* w) {
  GridMediumDesc d;
  const Param* density = st.find("density");
  if (!density) throw Error(st.loc, "uniformgrid medium needs \"float density\" (nx * ny * nz values)");
  if (density->type != "float") throw Error(density->loc, "uniformgrid medium: \"density\" must be float values (as pbrt-v4)");
  const std::vector<double> values = st.get_numbers("density");
  grid_shape(st, ctm, &d);
  check_count(st, "density", values.size(), 1, d);
  check_values(st, "density", values);
  const Rgb sa = coefficient(st, "sigma_a", textures, w), ss = coefficient(st, "sigma_s", textures, w);
  d.sigma_t_scale = (sa + ss) * scale_param(st);
  d.albedo = albedo_of(sa, ss);
  d.g = g_param(st);
  d.channels = 1;
  d.density.assign(values.begin(), values.end());
  return d;
}

// pbrt-v4's rgbgrid: per-sample RGB sigma_a and sigma_s (a grid not given is 1 everywhere), times scale.
GridMediumDesc rgb_grid(const Statement& st, const Mat4& ctm) {
  GridMediumDesc d;
  for (const char* name : {"sigma_a", "sigma_s"})
    if (const Param* p = st.find(name); p && p->type != "rgb" && p->type != "color")
      throw Error(p->loc, std::string("rgbgrid medium: \"") + name + "\" must be rgb values, one per sample");
  const std::vector<double> sa = st.get_numbers("sigma_a"), ss = st.get_numbers("sigma_s");
  if (sa.empty() && ss.empty()) throw Error(st.loc, "rgbgrid medium needs \"rgb sigma_a\" and/or \"rgb sigma_s\" grids");
  grid_shape(st, ctm, &d);
  if (!sa.empty()) check_count(st, "sigma_a", sa.size(), 3, d), check_values(st, "sigma_a", sa);
  if (!ss.empty()) check_count(st, "sigma_s", ss.size(), 3, d), check_values(st, "sigma_s", ss);
  const size_t n = size_t(d.nx) * d.ny * d.nz * 3;
  d.channels = 3;
  d.density.resize(n);
  d.albedo_nx = d.nx, d.albedo_ny = d.ny, d.albedo_nz = d.nz;
  d.albedo_values.resize(n);
  for (size_t i = 0; i < n; ++i) {
    const double a = sa.empty() ? 1.0 : sa[i], s = ss.empty() ? 1.0 : ss[i];
    d.density[i] = float(a + s);
    d.albedo_values[i] = a + s > 0.0 ? float(s / (a + s)) : 0.f;
  }
  d.sigma_t_scale = Rgb(scale_param(st));
  d.g = g_param(st);
  return d;
}

}  // namespace

void PbrtMedia::define(const Statement& st, const Mat4& ctm, const TextureTable& textures, LoadWarnings* w, SceneMedia* media) {
  const std::string& name = st.strings[0];
  if (named_.count(name)) throw Error(st.loc, "named medium \"" + name + "\" redefined (pbrt-v4 refuses this too)");
  const std::string type = st.get_string("type", "");
  if (type.empty()) throw Error(st.loc, "MakeNamedMedium \"" + name + "\" has no \"string type\"");
  // Emissive media are not rendered: the medium is read without its emission.
  for (const char* emission : {"Le", "Lescale", "temperature"})
    if (const Param* p = st.find(emission))
      w->add(p->loc, "MakeNamedMedium \"" + name + "\": emission (\"" + p->name + "\") of media is not supported; ignored");
  st.ignore({"temperaturecutoff", "temperatureoffset", "temperaturescale"});
  uint32_t index = 0;
  if (type == "homogeneous") {
    if (const Param* preset = st.find("preset"))
      throw Error(preset->loc, "medium \"preset\" is not supported; give \"sigma_a\" and \"sigma_s\" (pbrt-v4's presets list them in mm^-1)");
    const float scale = scale_param(st);
    const Rgb sa = coefficient(st, "sigma_a", textures, w) * scale, ss = coefficient(st, "sigma_s", textures, w) * scale;
    const float g = g_param(st);
    index = media->add_homogeneous(sa, ss, g);
  } else if (type == "uniformgrid" || type == "rgbgrid") {
    const GridMediumDesc d = type == "uniformgrid" ? uniform_grid(st, ctm, textures, w) : rgb_grid(st, ctm);
    try {
      index = media->add_grid(d);
    } catch (const Error& e) {
      throw Error(st.loc, e.what());
    }
  } else {
    throw Error(st.loc, "medium type \"" + type + "\" is not supported (homogeneous, uniformgrid, rgbgrid)");
  }
  named_[name] = index;
}

int PbrtMedia::interface_of(const Statement& st) {
  const std::string& inside = st.strings[0];
  const std::string& outside = st.strings.size() > 1 ? st.strings[1] : st.strings[0];
  if (inside.empty() && outside.empty()) return -1;
  interfaces_.push_back({inside, outside, st.loc});
  return int(interfaces_.size() - 1);
}

void PbrtMedia::bind(int id, const SceneCounts& before, const SceneCounts& after) {
  if (id < 0) return;
  if (after.triangles == before.triangles && after.spheres == before.spheres && after.lights == before.lights) return;
  bindings_.push_back({id, before, after});
}

void PbrtMedia::bind_interior(int id, uint32_t interior, const SceneCounts& before, const SceneCounts& after) {
  if (after.triangles == before.triangles && after.spheres == before.spheres) return;
  bindings_.push_back({id, before, after, int32_t(interior)});
}

int32_t PbrtMedia::resolve(const std::string& name, const FileLoc& loc) const {
  if (name.empty()) return kVacuum;
  const auto it = named_.find(name);
  if (it == named_.end()) throw Error(loc, "MediumInterface: medium \"" + name + "\" is not defined (no MakeNamedMedium \"" + name + "\")");
  return int32_t(it->second);
}

void PbrtMedia::finish(SceneMedia* media) const {
  std::vector<MediumInterface> resolved;
  for (const Interface& i : interfaces_) resolved.push_back(make_medium_interface(resolve(i.inside, i.loc), resolve(i.outside, i.loc)));
  for (const Binding& b : bindings_) {
    if (b.interior < 0) {
      bind_added(resolved[size_t(b.id)], b.before, b.after, media);
    } else {
      const int32_t outside = b.id >= 0 ? resolved[size_t(b.id)].outside : kVacuum;
      bind_added(make_medium_interface(b.interior, outside), b.before, b.after, media);
    }
  }
  if (camera_ >= 0) media->camera_medium = resolved[size_t(camera_)].outside;
}

}  // namespace pathspace::pbrt
