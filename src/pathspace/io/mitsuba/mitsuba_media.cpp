// Mitsuba media (see mitsuba_media.h), with each version's parameters and defaults:
//  - Mitsuba 3: homogeneous sigma_t (default 1) and albedo (default 0.75) times scale; heterogeneous
//    sigma_t and albedo, each a constant or a volume, times scale. A gridvolume spans the unit cube
//    of its to_world, or its file's bounding box under to_world with use_grid_bbox.
//  - Mitsuba 0.6: sigmaA and sigmaS, or sigmaT and albedo, times scale (its material presets are
//    refused); heterogeneous density and albedo volumes, a gridvolume at its file's bounding box
//    under toWorld.
// hg's g defaults to 0.8 in both, as there; a medium without <phase> is isotropic.
#include "pathspace/io/mitsuba/mitsuba_media.h"

#include <cmath>
#include <filesystem>
#include <utility>

#include "pathspace/io/mitsuba/mitsuba_volume_file.h"

namespace pathspace::mitsuba {

namespace {

// A medium parameter: a constant (float, rgb, spectrum, constvolume) or a gridvolume's samples.
struct VolumeParam {
  bool grid = false;
  Rgb constant;
  VolumeFile file;
  float world_to_grid[12] = {};
  FileLoc loc;
  std::string file_name;
};

FileLoc loc_of(const Object& o, const std::string& name) {
  const Property* p = o.find(name);
  return p ? o.doc().loc(p->node) : o.loc();
}

// Coefficients are finite and >= 0; albedos lie in [0, 1] as well (beyond 1 a medium would create light).
void check_value(const FileLoc& loc, const std::string& what, const Rgb& v, bool albedo) {
  for (int c = 0; c < 3; ++c)
    if (!std::isfinite(v[c]) || v[c] < 0.f || (albedo && v[c] > 1.f))
      throw Error(loc, "medium " + what + " must be finite and " + (albedo ? "within [0, 1]" : ">= 0") + " (got " + std::to_string(v.r) +
                           ", " + std::to_string(v.g) + ", " + std::to_string(v.b) + ")");
}

float scale_of(const Object& o) {
  const double s = o.get_float("scale", 1.0);
  if (!(s >= 0.0) || !std::isfinite(s)) throw Error(loc_of(o, "scale"), "medium scale must be finite and >= 0");
  return float(s);
}

void grid_volume(const Object& vol, const std::string& folder, LoadWarnings* w, VolumeParam* v) {
  const std::string file = vol.get_string("filename", "");
  if (file.empty()) throw Error(vol.loc(), "gridvolume needs a filename (a Mitsuba .vol file)");
  const std::filesystem::path path = vol.doc().resolve_file(file, folder);
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    throw Error(loc_of(vol, "filename"), "volume file '" + file + "' not found (looked for " + path.string() + ")");
  try {
    v->file = read_mitsuba_volume(path.string());
  } catch (const Error& e) {
    throw Error(vol.loc(), std::string("gridvolume: ") + e.what());
  }
  double lo[3] = {0, 0, 0}, hi[3] = {1, 1, 1};
  if (vol.doc().legacy() || vol.get_bool("use_grid_bbox", false))
    for (int a = 0; a < 3; ++a) lo[a] = v->file.bbox_min[a], hi[a] = v->file.bbox_max[a];
  bool animated = false;
  const Mat4 to_world = vol.get_transform("to_world", &animated);
  if (animated) w->add(vol.loc(), "gridvolume: an animated to_world keeps its first key");
  if (!pbrt::world_to_unit_box(to_world, lo, hi, v->world_to_grid))
    throw Error(vol.loc(), "gridvolume '" + file + "': its box is flat or its to_world singular");
  if (vol.get_string("filter_type", "trilinear") == "nearest")
    w->add(loc_of(vol, "filter_type"), "gridvolume: filter_type 'nearest' not supported; interpolated trilinearly");
  vol.ignore({"raw", "wrap_mode", "send_data", "accel"});
  v->grid = true;
  v->file_name = file;
}

VolumeParam volume_param(const Object& o, const std::string& name, const Rgb& fallback, const std::string& folder, LoadWarnings* w,
                         SpectrumUse use) {
  VolumeParam v;
  v.constant = fallback;
  v.loc = o.loc();
  const Property* p = o.find(name);
  if (!p) return v;
  v.loc = o.doc().loc(p->node);
  if (p->tag != "volume") {
    v.constant = o.get_rgb(name, fallback, folder, w, use);
    return v;
  }
  const Object vol(o.doc(), p->node);
  if (vol.type() == "constvolume") v.constant = vol.get_rgb("value", Rgb(0.75f), folder, w, use);
  else if (vol.type() == "gridvolume") grid_volume(vol, folder, w, &v);
  else throw Error(v.loc, "volume type '" + vol.type() + "' is not supported (constvolume, gridvolume)");
  vol.warn_unused(w);
  return v;
}

bool same_box(const VolumeParam& a, const VolumeParam& b) {
  for (int i = 0; i < 12; ++i)
    if (std::fabs(a.world_to_grid[i] - b.world_to_grid[i]) > 1e-5f * (1.f + std::fabs(a.world_to_grid[i]))) return false;
  return true;
}

}  // namespace

void MediaReader::define(const pugi::xml_node& node) {
  const std::string id = doc_.attr(node, "id");
  if (id.empty()) {
    w_->add(doc_.loc(node), "top-level <medium> without an id is never used; ignored");
    return;
  }
  if (ids_.count(id)) w_->add(doc_.loc(node), "medium id '" + id + "' redefined");
  ids_[id] = read(node);
}

bool MediaReader::is_medium_ref(const pugi::xml_node& ref) const {
  const std::string id = doc_.attr(ref, "id");
  if (ids_.count(id)) return true;
  const std::string name = doc_.prop_name(ref);
  if (name == "interior" || name == "exterior")
    throw Error(doc_.loc(ref), "<ref name=\"" + name + "\" id=\"" + id + "\"> names no <medium> defined before it");
  return false;
}

int32_t MediaReader::medium_of(const pugi::xml_node& node) {
  if (std::string(node.name()) == "medium") return int32_t(read(node));
  return int32_t(ids_.at(doc_.attr(node, "id")));  // is_medium_ref checked it
}

MediumInterface MediaReader::shape_media(const Object& shape) {
  int32_t side[2] = {kVacuum, kVacuum};
  bool given[2] = {false, false};
  for (const pugi::xml_node& n : shape.node().children()) {
    if (n.type() != pugi::node_element) continue;
    const std::string tag = n.name();
    if (tag != "medium" && !(tag == "ref" && is_medium_ref(n))) continue;
    const std::string name = doc_.prop_name(n);
    const int k = name == "interior" ? 0 : name == "exterior" ? 1 : -1;
    if (k < 0) throw Error(doc_.loc(n), "a shape's medium needs name=\"interior\" or name=\"exterior\"");
    if (given[k]) throw Error(doc_.loc(n), shape.title() + " has a second " + name + " medium");
    given[k] = true;
    side[k] = medium_of(n);
    shape.mark_used(n);
  }
  return make_medium_interface(side[0], side[1]);
}

int32_t MediaReader::endpoint_medium(const Object& o) {
  int32_t medium = kVacuum;
  bool found = false;
  for (const pugi::xml_node& n : o.node().children()) {
    if (n.type() != pugi::node_element) continue;
    const std::string tag = n.name();
    if (tag != "medium" && !(tag == "ref" && is_medium_ref(n))) continue;
    if (found) throw Error(doc_.loc(n), o.title() + " holds a second medium (Mitsuba takes one per sensor or emitter)");
    found = true;
    medium = medium_of(n);
    o.mark_used(n);
  }
  return medium;
}

uint32_t MediaReader::read(const pugi::xml_node& node) {
  const auto done = read_.find(node.internal_object());
  if (done != read_.end()) return done->second;
  const Object o(doc_, node);
  const float g = phase_g(o);
  uint32_t index = 0;
  if (o.type() == "homogeneous") index = homogeneous(o, g);
  else if (o.type() == "heterogeneous") index = heterogeneous(o, g);
  else throw Error(o.loc(), "medium type '" + o.type() + "' is not supported (homogeneous, heterogeneous)");
  // Sampling strategies and integration methods change the noise, not the expectation.
  o.ignore({"sample_emitters", "has_spectral_extinction", "strategy", "method", "step_size"});
  o.warn_unused(w_);
  read_[node.internal_object()] = index;
  const std::string id = doc_.attr(node, "id");
  if (!id.empty()) ids_[id] = index;  // a nested medium with an id can be referenced after it too
  return index;
}

float MediaReader::phase_g(const Object& o) {
  const std::vector<pugi::xml_node> phases = o.children("phase");
  if (phases.empty()) return 0.f;
  if (phases.size() > 1) throw Error(doc_.loc(phases[1]), o.title() + " has more than one <phase>");
  const Object ph(doc_, phases[0]);
  float g = 0.f;
  if (ph.type() == "hg") {
    g = float(ph.get_float("g", 0.8));
    if (!(g > -1.f && g < 1.f)) throw Error(loc_of(ph, "g"), "hg phase function: g must lie in (-1, 1) (got " + std::to_string(g) + ")");
  } else if (ph.type() != "isotropic") {
    w_->add(ph.loc(), "phase function '" + ph.type() + "' is not supported; isotropic used");
    ph.ignore_all();
  }
  ph.warn_unused(w_);
  return g;
}

uint32_t MediaReader::homogeneous(const Object& o, float g) {
  Rgb sigma_a, sigma_s;
  if (doc_.legacy()) {
    if (o.has("material"))
      throw Error(loc_of(o, "material"), "medium material presets are not supported; give sigmaA and sigmaS, or sigmaT and albedo");
    const bool as = o.has("sigma_a") || o.has("sigma_s"), ta = o.has("sigma_t") || o.has("albedo");
    if (as && ta) throw Error(o.loc(), o.title() + ": give sigmaA and sigmaS, or sigmaT and albedo, not both pairs (as Mitsuba 0.6)");
    if (!as && !ta)
      throw Error(o.loc(), o.title() + ": Mitsuba 0.6's default is its 'skin1' preset, which pathspace does not have; give sigmaA "
                                       "and sigmaS, or sigmaT and albedo");
    const char* pair[2] = {as ? "sigma_a" : "sigma_t", as ? "sigma_s" : "albedo"};
    for (const char* name : pair)
      if (!o.has(name)) throw Error(o.loc(), o.title() + ": '" + pair[0] + "' and '" + pair[1] + "' are both needed (no preset fills in)");
    const Rgb first = o.get_rgb(pair[0], Rgb(), folder_, w_, SpectrumUse::unbounded);
    const Rgb second = o.get_rgb(pair[1], Rgb(), folder_, w_, as ? SpectrumUse::unbounded : SpectrumUse::reflectance);
    check_value(loc_of(o, pair[0]), pair[0], first, false);
    check_value(loc_of(o, pair[1]), pair[1], second, !as);
    sigma_a = as ? first : first * (Rgb(1.f) - second);
    sigma_s = as ? second : first * second;
  } else {
    const VolumeParam t = volume_param(o, "sigma_t", Rgb(1.f), folder_, w_, SpectrumUse::unbounded);
    const VolumeParam a = volume_param(o, "albedo", Rgb(0.75f), folder_, w_, SpectrumUse::reflectance);
    for (const VolumeParam* v : {&t, &a})
      if (v->grid) throw Error(v->loc, "a homogeneous medium takes constants, not a gridvolume (use a heterogeneous medium)");
    check_value(t.loc, "sigma_t", t.constant, false);
    check_value(a.loc, "albedo", a.constant, true);
    sigma_a = t.constant * (Rgb(1.f) - a.constant);
    sigma_s = t.constant * a.constant;
  }
  const float scale = scale_of(o);
  return media_->add_homogeneous(sigma_a * scale, sigma_s * scale, g);
}

uint32_t MediaReader::heterogeneous(const Object& o, float g) {
  const std::string density = doc_.legacy() ? "density" : "sigma_t";  // 0.6: density; 3: sigma_t
  VolumeParam t = volume_param(o, density, Rgb(1.f), folder_, w_, SpectrumUse::unbounded);
  VolumeParam a = volume_param(o, "albedo", Rgb(0.75f), folder_, w_, SpectrumUse::reflectance);
  const float scale = scale_of(o);
  if (!a.grid) check_value(a.loc, "albedo", a.constant, true);
  if (!t.grid) {  // constant extinction: a homogeneous medium
    check_value(t.loc, density, t.constant, false);
    if (a.grid) throw Error(a.loc, "an albedo grid with a constant " + density + " is not supported");
    return media_->add_homogeneous(t.constant * (Rgb(1.f) - a.constant) * scale, t.constant * a.constant * scale, g);
  }
  GridMediumDesc d;
  d.sigma_t_scale = Rgb(scale);
  d.albedo = a.constant;
  d.g = g;
  std::copy(std::begin(t.world_to_grid), std::end(t.world_to_grid), d.world_to_grid);
  d.nx = t.file.nx, d.ny = t.file.ny, d.nz = t.file.nz, d.channels = t.file.channels;
  d.density = std::move(t.file.values);
  if (a.grid) {
    if (!same_box(t, a)) throw Error(a.loc, "the albedo grid must span the same box as the " + density + " grid (bounding box and to_world)");
    d.albedo_nx = a.file.nx, d.albedo_ny = a.file.ny, d.albedo_nz = a.file.nz;
    if (a.file.channels == 3) {
      d.albedo_values = std::move(a.file.values);
    } else {  // one channel: grey
      d.albedo_values.reserve(a.file.values.size() * 3);
      for (float x : a.file.values) d.albedo_values.insert(d.albedo_values.end(), {x, x, x});
    }
  }
  try {
    return media_->add_grid(d);
  } catch (const Error& e) {
    throw Error(o.loc(), o.title() + " ('" + t.file_name + (a.grid ? "', '" + a.file_name : std::string()) + "'): " + e.what());
  }
}

}  // namespace pathspace::mitsuba
