// One Mitsuba object element (<bsdf>, <shape>, <emitter>, <sensor>, ...) with its typed properties
// (<float name=... value=...>, <rgb>, <transform>, ...) and nested objects. Every lookup marks the
// property used, so whatever pathspace does not read becomes a warning with file:line afterwards.
#pragma once

#include <initializer_list>
#include <string>
#include <vector>

#include "pathspace/io/load_warnings.h"
#include "pathspace/io/mitsuba/mitsuba_xml.h"
#include "pathspace/io/pbrt/pbrt_transform.h"
#include "pathspace/io/spectrum/spectrum_to_rgb.h"
#include "pathspace/math/rgb.h"

namespace pathspace::mitsuba {

using Mat4 = pbrt::Mat4;  // the same row-major double 4x4 as the pbrt loader's

struct Property {
  pugi::xml_node node;
  std::string tag, name;  // "float", "max_depth" (snake_case whatever the file's version)
  mutable bool used = false;
};

class Object {
 public:
  Object(const Document& doc, const pugi::xml_node& node);

  const Document& doc() const { return *doc_; }
  const pugi::xml_node& node() const { return node_; }
  const std::string& tag() const { return tag_; }
  const std::string& type() const { return type_; }
  FileLoc loc() const { return doc_->loc(node_); }
  std::string title() const { return "<" + tag_ + " type=\"" + type_ + "\">"; }

  const Property* find(const std::string& name) const;  // marks it used
  bool has(const std::string& name) const { return find(name) != nullptr; }
  double get_float(const std::string& name, double fallback) const;
  int get_int(const std::string& name, int fallback) const;
  bool get_bool(const std::string& name, bool fallback) const;
  std::string get_string(const std::string& name, const std::string& fallback) const;
  Vec3 get_vector(const std::string& name, const Vec3& fallback) const;  // <point>/<vector>
  // rgb, srgb (decoded to linear), spectrum (constant, wavelength:value pairs or a file), blackbody
  // (temperature and scale, in W / (m^2 sr nm)), float, or a nested or referenced texture (a
  // bitmap's mean colour, with a warning; mitsuba_textures.h binds bitmaps where a material can use
  // the image). Spectra are converted as `use` says (io/spectrum/spectrum_to_rgb.h).
  Rgb get_rgb(const std::string& name, const Rgb& fallback, const std::string& folder, LoadWarnings* w,
              SpectrumUse use = SpectrumUse::reflectance) const;
  // <transform name=...>: its translate/rotate/scale/matrix/lookat children, each applied after
  // the previous ones (M = op * M); identity when absent. For an <animation name=...> (below) the
  // transform of its first key, and *animated (when given) is set.
  Mat4 get_transform(const std::string& name, bool* animated = nullptr) const;
  // <animation name=...> with <transform time="t"> keys (Mitsuba 2's and 3's animated transforms),
  // sorted by time; a plain <transform> (or none) is one key at time 0.
  struct TransformKeys {
    std::vector<double> times;
    std::vector<Mat4> transforms;
    bool animated() const { return transforms.size() > 1; }
    // The transform at `time`: interpolated between the keys around it as pbrt-v4 and Mitsuba
    // interpolate (io/pbrt/pbrt_animated_transform.h), the first or last key outside them.
    Mat4 at(double time, const FileLoc& loc) const;
  };
  TransformKeys get_transform_keys(const std::string& name) const;
  // Nested objects with this tag (<bsdf>, <emitter>, <ref>, ...), marked used.
  std::vector<pugi::xml_node> children(const std::string& tag) const;

  // A <texture> element as one colour: a bitmap's mean, a checkerboard's mean (with warnings).
  Rgb texture_rgb(const pugi::xml_node& node, const std::string& name, const Rgb& fallback, const std::string& folder,
                  LoadWarnings* w) const;

  void ignore(std::initializer_list<const char*> names) const;
  void ignore_all() const;
  // Marks the one nested element `node` used (a <ref> among others of the same tag).
  void mark_used(const pugi::xml_node& node) const;
  // One warning per property or nested object nobody read.
  void warn_unused(LoadWarnings* w) const;

 private:
  Mat4 parse_transform(const pugi::xml_node& node) const;  // a <transform>'s operations
  const Document* doc_;
  pugi::xml_node node_;
  std::string tag_, type_;
  std::vector<Property> props_;  // nested objects too, with their tag
};

// True for element names that are property values (float, rgb, transform, ...).
bool is_property_tag(const std::string& tag);

}  // namespace pathspace::mitsuba
