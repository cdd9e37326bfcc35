#include "pathspace/io/camera_path_file.h"

#include <cmath>

#include <nlohmann/json.hpp>

#include "pathspace/base/error.h"
#include "pathspace/io/file_bytes.h"
#include "pathspace/scene/scene_validation.h"

namespace pathspace {

namespace {

using nlohmann::json;

// Line and column (1-based) of a byte offset, for JSON syntax errors.
FileLoc location_of(const std::string& text, size_t offset, const std::string& name) {
  FileLoc loc{name, 1, 1};
  for (size_t i = 0; i < offset && i < text.size(); ++i) {
    if (text[i] == '\n') ++loc.line, loc.column = 1;
    else ++loc.column;
  }
  return loc;
}

struct KeyReader {
  const std::string& name;
  size_t index;

  [[noreturn]] void fail(const std::string& what) const {
    throw Error(FileLoc{name}, "keyframe " + std::to_string(index) + ": " + what);
  }
  double number(const json& k, const char* field, double lo, double hi) const {
    if (!k.contains(field)) fail(std::string("'") + field + "' is missing");
    const json& v = k.at(field);
    if (!v.is_number()) fail(std::string("'") + field + "' must be a number");
    const double x = v.get<double>();
    if (!(x >= lo && x <= hi)) fail(std::string("'") + field + "' is " + v.dump() + ", outside [" + json(lo).dump() + ", " + json(hi).dump() + "]");
    return x;
  }
  Vec3 vec3(const json& k, const char* field) const {
    if (!k.contains(field)) fail(std::string("'") + field + "' is missing");
    const json& v = k.at(field);
    if (!v.is_array() || v.size() != 3) fail(std::string("'") + field + "' must be an array of three numbers [x, y, z]");
    float c[3];
    for (int i = 0; i < 3; ++i) {
      if (!v[size_t(i)].is_number()) fail(std::string("'") + field + "' must be an array of three numbers [x, y, z]");
      const double x = v[size_t(i)].get<double>();
      if (!(std::fabs(x) <= double(kMaxSceneCoordinate)))
        fail(std::string("'") + field + "' holds " + v[size_t(i)].dump() + ", beyond the scene coordinate limit");
      c[i] = float(x);
    }
    return {c[0], c[1], c[2]};
  }
};

}  // namespace

CameraPath parse_camera_path(const std::string& text, const std::string& name) {
  json doc;
  try {
    doc = json::parse(text);
  } catch (const json::parse_error& e) {
    // e.byte is 1-based and points just past the offending character.
    throw Error(location_of(text, e.byte > 0 ? e.byte - 1 : 0, name), std::string("not valid JSON: ") + e.what());
  }
  if (!doc.is_object() || !doc.contains("keyframes") || !doc.at("keyframes").is_array())
    throw Error(FileLoc{name}, "a camera path is an object with an array \"keyframes\" (docs/animation.md)");
  const json& keys = doc.at("keyframes");
  if (keys.empty()) throw Error(FileLoc{name}, "the camera path has no keyframes");
  CameraPath path;
  for (size_t i = 0; i < keys.size(); ++i) {
    const KeyReader r{name, i};
    const json& k = keys[i];
    if (!k.is_object()) r.fail("must be an object");
    for (const auto& item : k.items())
      if (item.key() != "time" && item.key() != "position" && item.key() != "target" && item.key() != "up" && item.key() != "fov")
        r.fail("unknown field '" + item.key() + "' (time, position, target, up, fov)");
    CameraKeyframe key;
    key.time = r.number(k, "time", -1e9, 1e9);
    key.position = r.vec3(k, "position");
    key.target = r.vec3(k, "target");
    if (k.contains("up")) key.up = r.vec3(k, "up");
    if (k.contains("fov")) key.fov_degrees = float(r.number(k, "fov", 0.01, 179.0));
    const Vec3 forward = key.target - key.position;
    if (!(length(forward) > 0.f)) r.fail("position and target coincide");
    if (!(length(cross(normalize(forward), key.up)) > 1e-6f)) r.fail("'up' is zero or parallel to the view direction");
    if (!path.keys.empty() && !(key.time > path.keys.back().time)) r.fail("times must increase from keyframe to keyframe");
    path.keys.push_back(key);
  }
  return path;
}

CameraPath read_camera_path(const std::string& path) {
  return parse_camera_path(read_file_as_stored(path), path);
}

}  // namespace pathspace
