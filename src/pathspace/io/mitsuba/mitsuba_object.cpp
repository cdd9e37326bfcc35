// Typed property access for Mitsuba objects (see mitsuba_object.h). Values are parsed on lookup,
// so a malformed value that pathspace never reads cannot fail the load, and every error points at
// the property's own line.
#include "pathspace/io/mitsuba/mitsuba_object.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "pathspace/io/image_io.h"
#include "pathspace/io/pbrt/pbrt_animated_transform.h"
#include "pathspace/io/spectrum/spectrum_to_rgb.h"

namespace pathspace::mitsuba {

namespace {

const char* const kPropertyTags[] = {"float", "integer", "boolean", "string", "rgb", "srgb", "spectrum",
                                     "point", "vector", "transform", "blackbody", "color", "animation"};

float srgb_to_linear(double c) { return float(c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4)); }

Rgb rgb_value(const std::vector<double>& v, const FileLoc& loc) {
  if (v.size() == 1) return Rgb(float(v[0]));
  if (v.size() == 3) return Rgb(float(v[0]), float(v[1]), float(v[2]));
  throw Error(loc, "a colour needs 1 or 3 values");
}

}  // namespace

bool is_property_tag(const std::string& tag) {
  for (const char* t : kPropertyTags)
    if (tag == t) return true;
  return false;
}

Object::Object(const Document& doc, const pugi::xml_node& node)
    : doc_(&doc), node_(node), tag_(node.name()), type_(doc.attr(node, "type")) {
  for (const pugi::xml_node& c : node.children()) {
    if (c.type() != pugi::node_element) continue;
    props_.push_back(Property{c, c.name(), doc.prop_name(c)});
  }
}

const Property* Object::find(const std::string& name) const {
  const Property* found = nullptr;
  for (const Property& p : props_)
    if (p.name == name && !name.empty()) {
      p.used = true;
      found = &p;  // the last definition wins, as in Mitsuba
    }
  return found;
}

double Object::get_float(const std::string& name, double fallback) const {
  const Property* p = find(name);
  if (!p) return fallback;
  if (p->tag != "float" && p->tag != "integer")
    throw Error(doc_->loc(p->node), "property '" + name + "' must be a <float>, not <" + p->tag + ">");
  return parse_number(doc_->attr(p->node, "value"), doc_->loc(p->node));
}

int Object::get_int(const std::string& name, int fallback) const {
  const Property* p = find(name);
  if (!p) return fallback;
  if (p->tag != "integer") throw Error(doc_->loc(p->node), "property '" + name + "' must be an <integer>, not <" + p->tag + ">");
  const double v = parse_number(doc_->attr(p->node, "value"), doc_->loc(p->node));
  if (v != std::floor(v) || std::fabs(v) > 2e9) throw Error(doc_->loc(p->node), "property '" + name + "' must be an integer");
  return int(v);
}

bool Object::get_bool(const std::string& name, bool fallback) const {
  const Property* p = find(name);
  if (!p) return fallback;
  const std::string v = doc_->attr(p->node, "value");
  if (p->tag != "boolean" || (v != "true" && v != "false"))
    throw Error(doc_->loc(p->node), "property '" + name + "' must be <boolean value=\"true\"|\"false\">");
  return v == "true";
}

std::string Object::get_string(const std::string& name, const std::string& fallback) const {
  const Property* p = find(name);
  if (!p) return fallback;
  if (p->tag != "string") throw Error(doc_->loc(p->node), "property '" + name + "' must be a <string>, not <" + p->tag + ">");
  return doc_->attr(p->node, "value");
}

Vec3 Object::get_vector(const std::string& name, const Vec3& fallback) const {
  const Property* p = find(name);
  if (!p) return fallback;
  const FileLoc loc = doc_->loc(p->node);
  if (p->tag != "point" && p->tag != "vector") throw Error(loc, "property '" + name + "' must be a <point> or <vector>");
  if (doc_->has_attr(p->node, "value")) {
    const std::vector<double> v = parse_numbers(doc_->attr(p->node, "value"), loc);
    if (v.size() != 3) throw Error(loc, "property '" + name + "' needs 3 values");
    return Vec3(float(v[0]), float(v[1]), float(v[2]));
  }
  return Vec3(float(parse_number(doc_->attr(p->node, "x", "0"), loc)), float(parse_number(doc_->attr(p->node, "y", "0"), loc)),
              float(parse_number(doc_->attr(p->node, "z", "0"), loc)));
}

Rgb Object::get_rgb(const std::string& name, const Rgb& fallback, const std::string& folder, LoadWarnings* w,
                    SpectrumUse use) const {
  const Property* p = find(name);
  if (!p) return fallback;
  const FileLoc loc = doc_->loc(p->node);
  const std::string value = doc_->attr(p->node, "value");
  if (p->tag == "rgb" || p->tag == "color" || p->tag == "float") return rgb_value(parse_numbers(value, loc), loc);
  if (p->tag == "srgb") {
    const Rgb c = rgb_value(parse_numbers(value, loc), loc);
    return Rgb(srgb_to_linear(c.r), srgb_to_linear(c.g), srgb_to_linear(c.b));
  }
  if (p->tag == "spectrum") {
    if (doc_->has_attr(p->node, "filename")) {
      const std::string file = doc_->attr(p->node, "filename");
      const std::filesystem::path path = doc_->resolve_file(file, folder);
      std::error_code ec;
      if (!std::filesystem::is_regular_file(path, ec))
        throw Error(loc, "spectrum file '" + file + "' not found (looked for " + path.string() + ")");
      return spectrum_to_rgb(read_spd_file(path.string()), use);
    }
    if (value.find(':') == std::string::npos) return rgb_value(parse_numbers(value, loc), loc);
    std::string numbers = value;
    for (char& c : numbers)
      if (c == ':') c = ' ';
    return spectrum_to_rgb(spectrum_from_pairs(parse_numbers(numbers, loc), loc, "spectrum '" + name + "'"), use);
  }
  if (p->tag == "blackbody") {
    std::string kelvin = doc_->attr(p->node, "temperature");
    if (!kelvin.empty() && (kelvin.back() == 'K' || kelvin.back() == 'k')) kelvin.pop_back();
    const double scale = parse_number(doc_->attr(p->node, "scale", "1"), loc);
    return spectrum_to_rgb(blackbody_spectrum(parse_number(kelvin, loc), BlackbodyUnit::radiance_per_nm, loc), use) * float(scale);
  }
  if (p->tag == "texture") return texture_rgb(p->node, name, fallback, folder, w);
  if (p->tag == "ref") {
    const std::string id = doc_->attr(p->node, "id");
    const pugi::xml_node tex = doc_->texture(id);
    if (!tex) throw Error(loc, "<ref id=\"" + id + "\"> names no top-level <texture>");
    return texture_rgb(tex, name, fallback, folder, w);
  }
  throw Error(loc, "property '" + name + "' must be a colour (<rgb>, <spectrum>, <float> or <texture>), not <" + p->tag + ">");
}

Rgb Object::texture_rgb(const pugi::xml_node& node, const std::string& name, const Rgb& fallback, const std::string& folder,
                        LoadWarnings* w) const {
  const FileLoc loc = doc_->loc(node);
  // Textures nest (a checkerboard of textures); a bound keeps hostile files from exhausting the stack.
  static thread_local int depth = 0;
  struct Guard {
    Guard() { ++depth; }
    ~Guard() { --depth; }
  } guard;
  if (depth > 16) throw Error(loc, "textures nested more than 16 deep");
  const Object tex(*doc_, node);
  if (tex.type() == "bitmap") {
    const std::string file = tex.get_string("filename", "");
    const std::filesystem::path path = doc_->resolve_file(file, folder);
    std::error_code ec;
    if (file.empty() || !std::filesystem::is_regular_file(path, ec))
      throw Error(loc, "texture file '" + file + "' not found (looked for " + path.string() + ")");
    Image image;
    try {
      image = read_image(path.string(), tex.get_bool("raw", false) ? LdrEncoding::linear : LdrEncoding::srgb);
    } catch (const Error& e) {
      throw Error(loc, "bitmap texture: " + std::string(e.what()));
    }
    double sum[3] = {0, 0, 0};
    for (const Rgb& c : image.pixels)
      for (int i = 0; i < 3; ++i) sum[i] += c[i];
    const double n = double(std::max<size_t>(1, image.pixels.size()));
    const Rgb mean(float(sum[0] / n), float(sum[1] / n), float(sum[2] / n));
    if (!all_finite(mean)) throw Error(loc, "bitmap texture '" + file + "' holds NaN or infinite values");
    tex.ignore({"filter_type", "wrap_mode", "to_uv", "format"});
    tex.warn_unused(w);
    w->add(loc, "bitmap texture '" + file + "' for '" + name + "' approximated by its mean colour (" + std::to_string(mean.r) + ", " +
                    std::to_string(mean.g) + ", " + std::to_string(mean.b) +
                    "): only diffuse reflectances (diffuse, plastic) are textured");
    return mean;
  }
  if (tex.type() == "checkerboard") {
    w->add(loc, "checkerboard texture for '" + name + "' approximated by the mean of its two colours");
    const Rgb c = (tex.get_rgb("color0", Rgb(0.4f), folder, w) + tex.get_rgb("color1", Rgb(0.2f), folder, w)) * 0.5f;
    tex.ignore({"to_uv"});
    tex.warn_unused(w);
    return c;
  }
  tex.ignore_all();
  w->add(loc, "texture type '" + tex.type() + "' not supported; '" + name + "' uses its default");
  return fallback;
}

Mat4 Object::get_transform(const std::string& name, bool* animated) const {
  const TransformKeys keys = get_transform_keys(name);
  if (animated) *animated = keys.animated();
  return keys.transforms.front();
}

Object::TransformKeys Object::get_transform_keys(const std::string& name) const {
  const Property* p = find(name);
  TransformKeys keys;
  if (!p) {
    keys.times.push_back(0.0);
    keys.transforms.push_back(Mat4());
    return keys;
  }
  if (p->tag == "transform") {
    keys.times.push_back(0.0);
    keys.transforms.push_back(parse_transform(p->node));
    return keys;
  }
  if (p->tag != "animation") throw Error(doc_->loc(p->node), "property '" + name + "' must be a <transform> or an <animation>");
  std::vector<std::pair<double, Mat4>> sorted;
  for (const pugi::xml_node& key : p->node.children()) {
    if (key.type() != pugi::node_element) continue;
    const FileLoc loc = doc_->loc(key);
    if (std::string(key.name()) != "transform") throw Error(loc, "<animation> holds <transform time=...> keys only");
    if (!doc_->has_attr(key, "time")) throw Error(loc, "an <animation> key needs a time attribute");
    const double time = parse_number(doc_->attr(key, "time"), loc);
    if (!std::isfinite(time)) throw Error(loc, "an <animation> key's time must be finite");
    for (const auto& [t, m] : sorted)
      if (t == time) throw Error(loc, "two <animation> keys at the same time");
    sorted.emplace_back(time, parse_transform(key));
  }
  if (sorted.empty()) throw Error(doc_->loc(p->node), "<animation> without <transform time=...> keys");
  std::sort(sorted.begin(), sorted.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  for (const auto& [t, m] : sorted) {
    keys.times.push_back(t);
    keys.transforms.push_back(m);
  }
  return keys;
}

Mat4 Object::TransformKeys::at(double time, const FileLoc& loc) const {
  if (time <= times.front()) return transforms.front();
  if (time >= times.back()) return transforms.back();
  size_t k = 1;
  while (times[k] < time) ++k;
  Mat4 out;
  if (!pbrt::animated_transform_at(transforms[k - 1], transforms[k], times[k - 1], times[k], time, &out))
    throw Error(loc, "the animated transform cannot be interpolated (a singular key)");
  return out;
}

Mat4 Object::parse_transform(const pugi::xml_node& node) const {
  Mat4 m;
  for (const pugi::xml_node& op : node.children()) {
    if (op.type() != pugi::node_element) continue;
    const std::string t = op.name();
    const FileLoc loc = doc_->loc(op);
    auto num = [&](const char* key, const char* fallback) { return parse_number(doc_->attr(op, key, fallback), loc); };
    auto triple = [&](const char* fallback) {  // value="x y z" or x=, y=, z= attributes
      if (doc_->has_attr(op, "value")) {
        std::vector<double> v = parse_numbers(doc_->attr(op, "value"), loc);
        if (v.size() == 1 && t == "scale") v = {v[0], v[0], v[0]};
        if (v.size() != 3) throw Error(loc, "<" + t + "> needs 3 values");
        return v;
      }
      return std::vector<double>{num("x", fallback), num("y", fallback), num("z", fallback)};
    };
    Mat4 o;
    if (t == "translate") {
      const auto v = triple("0");
      o = Mat4::translate(v[0], v[1], v[2]);
    } else if (t == "scale") {
      const auto v = triple("1");
      o = Mat4::scale(v[0], v[1], v[2]);
    } else if (t == "rotate") {
      const auto v = triple("0");
      const std::optional<Mat4> r = Mat4::rotate(num("angle", "0"), v[0], v[1], v[2]);
      if (!r) throw Error(loc, "<rotate> needs an axis of nonzero length (x, y, z)");
      o = *r;
    } else if (t == "matrix") {
      const std::vector<double> v = parse_numbers(doc_->attr(op, "value"), loc);
      if (v.size() != 16 && v.size() != 9) throw Error(loc, "<matrix> needs 16 (or 9) values");
      const int n = v.size() == 16 ? 4 : 3;
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) o.m[i][j] = v[size_t(i * n + j)];  // row-major, unlike pbrt
    } else if (t == "lookat") {
      auto point = [&](const char* key, const char* fallback) {
        const std::vector<double> v = parse_numbers(doc_->attr(op, key, fallback), loc);
        if (v.size() != 3) throw Error(loc, std::string("<lookat> attribute '") + key + "' needs 3 values");
        return Vec3(float(v[0]), float(v[1]), float(v[2]));
      };
      // Mitsuba's to_world columns are [cross(up, dir), up', dir, origin]: the inverse of pbrt's LookAt.
      Mat4 camera_from_world;
      if (!pbrt::look_at(point("origin", ""), point("target", ""), point("up", "0 1 0"), &camera_from_world) ||
          !camera_from_world.inverse(&o))
        throw Error(loc, "<lookat>: the up vector is parallel to the view direction (or origin == target)");
    } else {
      throw Error(loc, "unknown transform operation <" + t + ">");
    }
    m = o * m;
  }
  return m;
}

std::vector<pugi::xml_node> Object::children(const std::string& tag) const {
  std::vector<pugi::xml_node> out;
  for (const Property& p : props_)
    if (p.tag == tag) {
      p.used = true;
      out.push_back(p.node);
    }
  return out;
}

void Object::ignore(std::initializer_list<const char*> names) const {
  for (const char* n : names) find(n);
}

void Object::mark_used(const pugi::xml_node& node) const {
  for (const Property& p : props_)
    if (p.node == node) p.used = true;
}

void Object::ignore_all() const {
  for (const Property& p : props_) p.used = true;
}

void Object::warn_unused(LoadWarnings* w) const {
  for (const Property& p : props_) {
    if (p.used) continue;
    const std::string what = p.name.empty() ? "<" + p.tag + ">" : "<" + p.tag + " name=\"" + p.name + "\">";
    w->add(doc_->loc(p.node), title() + ": " + what + " is not supported; ignored");
  }
}

}  // namespace pathspace::mitsuba
