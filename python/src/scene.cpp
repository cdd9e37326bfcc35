// pathspace.Scene and pathspace.Camera: scenes by built-in name or file, the camera as plain values
// (position, target, up, fov, resolution, thin lens) that can be read, changed and set back.
#include <cmath>
#include <optional>
#include <utility>

#include <pybind11/stl.h>

#include "bindings.h"
#include "errors.h"
#include "py_scene.h"
#include "pathspace/io/scene_loader.h"
#include "pathspace/options/option_spec.h"
#include "pathspace/scene/builtin_scenes.h"
#include "pathspace/scene/scene_validation.h"
#include "pathspace/session/run_options.h"

namespace pathspace::python {

namespace {

// The camera as a user writes it. The field of view spans the shorter image axis (pbrt's convention).
struct CameraValues {
  Vec3 position, target, up;
  float fov = 0.f;
  int width = 0, height = 0;
  float lens_radius = 0.f, focus_distance = 1.f;

  bool operator==(const CameraValues& o) const {
    auto same = [](const Vec3& a, const Vec3& b) { return a.x == b.x && a.y == b.y && a.z == b.z; };
    return same(position, o.position) && same(target, o.target) && same(up, o.up) && fov == o.fov && width == o.width &&
           height == o.height && lens_radius == o.lens_radius && focus_distance == o.focus_distance;
  }
};

CameraValues values_of(const PerspectiveCamera& c) {
  CameraValues v;
  v.position = c.position;
  v.target = c.position + c.forward;  // a point on the view axis, one unit ahead
  v.up = c.up;
  v.fov = float(2.0 * std::atan(double(std::min(c.tan_x, c.tan_y))) * 180.0 / 3.14159265358979323846);
  v.width = c.width;
  v.height = c.height;
  v.lens_radius = c.lens_radius;
  v.focus_distance = c.focus_distance;
  return v;
}

void check_point(const Vec3& p, const char* what) {
  for (float x : {p.x, p.y, p.z})
    if (!(std::fabs(x) <= kMaxSceneCoordinate))
      throw py::value_error(std::string("Camera.") + what + ": each coordinate must be finite and within +-1e9");
}

// A camera from values, with the handedness of `current` (pbrt files may hold left-handed cameras).
PerspectiveCamera camera_of(const CameraValues& v, const PerspectiveCamera& current) {
  check_point(v.position, "position");
  check_point(v.target, "target");
  check_point(v.up, "up");
  if (!(v.fov >= 0.01f && v.fov <= 179.f)) throw py::value_error("Camera.fov must be between 0.01 and 179 degrees");
  check_image_size(v.width, v.height);  // OptionError: ValueError
  const Vec3 forward = v.target - v.position;
  if (!(length(forward) > 0.f)) throw py::value_error("Camera: position and target coincide");
  if (!(length(v.up) > 0.f)) throw py::value_error("Camera.up must not be zero");
  const Vec3 side = cross(normalize(forward), normalize(v.up));
  if (!(length(side) > 1e-6f)) throw py::value_error("Camera.up is parallel to the view direction");
  const float handedness = dot(cross(current.forward, current.up), current.right) < 0.f ? -1.f : 1.f;
  PerspectiveCamera c = make_file_camera(v.position, forward, side * handedness, cross(normalize(side), normalize(forward)), v.fov,
                                         v.width, v.height);
  if (!(v.lens_radius >= 0.f && v.lens_radius <= kMaxSceneCoordinate)) throw py::value_error("Camera.lens_radius must be 0 (pinhole) to 1e9");
  if (v.lens_radius > 0.f && !(v.focus_distance > 0.f && v.focus_distance <= kMaxSceneCoordinate))
    throw py::value_error("Camera.focus_distance must be positive (up to 1e9) for a thin lens");
  set_thin_lens(&c, v.lens_radius, v.lens_radius > 0.f ? v.focus_distance : current.focus_distance);
  return c;
}

py::tuple tuple_of(const Vec3& v) { return py::make_tuple(v.x, v.y, v.z); }
Vec3 vec3_of(const std::array<float, 3>& a) { return Vec3(a[0], a[1], a[2]); }

std::shared_ptr<PyScene> load(const std::string& name, std::optional<std::pair<int, int>> resolution, bool substitute_missing_textures,
                              std::optional<std::map<std::string, std::string>> defines, std::optional<std::string> animation) {
  if (name.empty()) throw py::value_error("Scene.load: the scene name is empty (see pathspace.builtin_scenes())");
  if (resolution) check_image_size(resolution->first, resolution->second);  // OptionError: ValueError
  std::vector<std::string> warnings;
  const int width = resolution ? resolution->first : kDefaultImageSide, height = resolution ? resolution->second : kDefaultImageSide;
  try {
    if (!names_scene_file(name)) {
      const BuiltinSceneInfo* info = find_builtin_scene(name);
      if (!info) {
        std::string names;
        for (const BuiltinSceneInfo& b : builtin_scenes()) names += (names.empty() ? "" : ", ") + b.name;
        throw Error("unknown scene '" + name + "': not a scene file, nor a built-in scene (" + names + ")");
      }
      if (substitute_missing_textures || defines || animation)
        throw py::value_error("substitute_missing_textures, defines and animation apply to scene files only");
      Scene scene = make_builtin_scene(info->name, width, height);
      // As `pathspace render` does (apply_scene_options): the default light selection, not the one
      // a built-in scene's library function sets for its paper's setup.
      scene.light_selection = kDefaultLightSelection;
      scene.finalize();
      validate_scene(scene, &warnings);
      return std::make_shared<PyScene>(std::move(scene), info->name, "", 0, std::move(warnings));
    }
    SceneLoadOptions options;
    if (resolution) options.width = width, options.height = height;
    options.substitute_missing_textures = substitute_missing_textures;
    if (defines)
      for (const auto& [key, value] : *defines) {
        if (!is_scene_parameter_name(key)) throw py::value_error("defines: '" + key + "' is not a parameter name (letters, digits and '_')");
        options.defines.emplace_back(key, value);
      }
    if (animation) options.animation = *animation;
    SceneFileSettings settings;
    Scene scene = load_scene(name, options, &warnings, &settings);
    validate_scene(scene, &warnings);
    return std::make_shared<PyScene>(std::move(scene), name, name, settings.spp, std::move(warnings));
  } catch (const OptionError&) {
    throw;
  } catch (const Error& e) {
    throw SceneLoadError(e);
  }
}

}  // namespace

void bind_scene(py::module_& m) {
  py::class_<CameraValues>(m, "Camera",
                           "A perspective camera as values: position, target (a point it looks at), up, fov (degrees, of "
                           "the shorter image axis), resolution (width, height), lens_radius (0: pinhole) and "
                           "focus_distance. Change it and assign it back: scene.camera = camera.")
      .def(py::init<>())
      .def_property(
          "position", [](const CameraValues& c) { return tuple_of(c.position); },
          [](CameraValues& c, const std::array<float, 3>& a) { c.position = vec3_of(a); })
      .def_property(
          "target", [](const CameraValues& c) { return tuple_of(c.target); },
          [](CameraValues& c, const std::array<float, 3>& a) { c.target = vec3_of(a); })
      .def_property(
          "up", [](const CameraValues& c) { return tuple_of(c.up); }, [](CameraValues& c, const std::array<float, 3>& a) { c.up = vec3_of(a); })
      .def_readwrite("fov", &CameraValues::fov)
      .def_property(
          "resolution", [](const CameraValues& c) { return py::make_tuple(c.width, c.height); },
          [](CameraValues& c, const std::pair<int, int>& r) { c.width = r.first, c.height = r.second; })
      .def_readwrite("lens_radius", &CameraValues::lens_radius)
      .def_readwrite("focus_distance", &CameraValues::focus_distance)
      .def("__eq__", [](const CameraValues& a, const CameraValues& b) { return a == b; })
      .def("__repr__", [](const CameraValues& c) {
        return py::str("Camera(position={}, target={}, up={}, fov={}, resolution={}, lens_radius={}, focus_distance={})")
            .format(tuple_of(c.position), tuple_of(c.target), tuple_of(c.up), c.fov, py::make_tuple(c.width, c.height), c.lens_radius,
                    c.focus_distance);
      });

  py::class_<PyScene, std::shared_ptr<PyScene>>(m, "Scene", "A scene to render: a built-in scene or a scene file (Scene.load).")
      .def_static("load", &load, py::arg("name"), py::kw_only(), py::arg("resolution") = py::none(),
                  py::arg("substitute_missing_textures") = false, py::arg("defines") = py::none(), py::arg("animation") = py::none(),
                  "Loads a scene file (.pbrt, .xml, .gltf, .glb, .ply, .obj, each optionally .gz) or builds a built-in scene "
                  "by name or id. resolution=(width, height) replaces the file's (default 512x512 for built-in scenes); "
                  "defines={'name': 'value'} sets Mitsuba scene parameters; animation picks a glTF animation. Raises "
                  "SceneError with file:line:column.")
      .def_property_readonly("name", &PyScene::label, "The built-in scene's name or the file's path.")
      .def_property_readonly("file", [](const PyScene& s) { return s.file().empty() ? py::object(py::none()) : py::object(py::str(s.file())); },
                             "The scene file, or None for a built-in scene.")
      .def_property_readonly("warnings", &PyScene::warnings, "What loading and validation noticed (file:line: message).")
      .def_property_readonly("file_spp", &PyScene::file_spp, "The file's samples per pixel (pbrt Sampler), 0: none.")
      .def_property(
          "camera", [](const PyScene& s) { return values_of(s.scene()->camera); },
          [](PyScene& s, const CameraValues& v) {
            const PerspectiveCamera& current = s.scene()->camera;
            if (v == values_of(current)) return;
            s.set_camera(camera_of(v, current));
          },
          "A copy of the camera's values; assign a changed one to move the camera.")
      .def_property(
          "light_selection", [](const PyScene& s) { return light_selection_name(s.scene()->light_selection); },
          [](PyScene& s, const std::string& v) {
            LightSelection selection;
            if (!parse_light_selection(v, &selection))
              throw py::value_error("light_selection must be 'uniform', 'power' or 'bvh', not '" + v + "'");
            s.set_light_selection(selection);
          },
          "How lights are picked for sampling: 'uniform', 'power' or 'bvh' (the CLI's --light-selection).")
      .def_property_readonly(
          "bounding_sphere",
          [](const PyScene& s) {
            const BoundingSphere b = s.scene()->bounds();
            return py::make_tuple(tuple_of(b.center), b.radius);
          },
          "(centre, radius) of the scene's bounding sphere (the centre is what the CLI's --orbit turns about).")
      .def("__repr__", [](const PyScene& s) {
        const PerspectiveCamera& c = s.scene()->camera;
        return py::str("<pathspace.Scene '{}' {}x{}>").format(s.label(), c.width, c.height);
      });

  m.def(
      "builtin_scenes",
      [] {
        py::list out;
        for (const BuiltinSceneInfo& b : builtin_scenes()) out.append(b.name);
        return out;
      },
      "The built-in scenes' names (pathspace.builtin_scene_info() gives their ids and descriptions).");
  m.def(
      "builtin_scene_info",
      [] {
        py::list out;
        for (const BuiltinSceneInfo& b : builtin_scenes()) {
          py::dict d;
          d["name"] = b.name;
          d["id"] = b.id;
          d["description"] = b.description;
          out.append(d);
        }
        return out;
      },
      "The built-in scenes as dicts: name, id (SmallVCM's), description.");
}

}  // namespace pathspace::python
