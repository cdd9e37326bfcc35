// Scene file dispatch by extension and the camera helpers shared by the loaders (see scene_loader.h).
// OBJ and PLY carry no lights or camera of their own: without emitters they get a white constant
// environment (with a warning), and the camera frames the bounding sphere unless options give one.
#include "pathspace/io/scene_loader.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <new>
#include <stdexcept>
#include <memory>

#include "pathspace/io/file_bytes.h"
#include "pathspace/io/gltf/gltf_animation.h"
#include "pathspace/io/gltf/gltf_loader.h"
#include "pathspace/io/load_warnings.h"
#include "pathspace/io/mitsuba/mitsuba_loader.h"
#include "pathspace/io/obj_loader.h"
#include "pathspace/io/pbrt/pbrt_scene_builder.h"
#include "pathspace/options/option_spec.h"
#include "pathspace/io/ply_reader.h"
#include "pathspace/scene/builtin_scenes.h"

namespace pathspace {

namespace {

constexpr float kDefaultFov = 45.f;
constexpr int kDefaultSize = 512;

void add_ply_mesh(const std::string& path, Scene* scene) {
  const PlyMesh mesh = read_ply(path);
  Material m = make_diffuse(Rgb(0.5f));
  m.two_sided = true;
  const uint32_t material = scene->add_material(m);
  const uint32_t base = uint32_t(scene->positions.size());
  scene->positions.insert(scene->positions.end(), mesh.positions.begin(), mesh.positions.end());
  if (mesh.normals.size() == mesh.positions.size()) {  // smooth shading (the material is untextured: uvs unused)
    scene->normals.resize(base);
    for (const Vec3& n : mesh.normals) scene->normals.push_back(all_finite(n) ? n : Vec3());
  }
  for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3)
    scene->triangles.push_back(Triangle{{base + mesh.indices[t], base + mesh.indices[t + 1], base + mesh.indices[t + 2]}, material, kNoLight});
}

}  // namespace

bool is_scene_file(const std::string& path) {
  const std::string ext = scene_file_extension(path);
  return ext == ".pbrt" || ext == ".xml" || ext == ".ply" || ext == ".obj" || ext == ".gltf" || ext == ".glb";
}

PerspectiveCamera make_file_camera(const Vec3& position, const Vec3& forward, const Vec3& right, const Vec3& up, float fov_degrees,
                               int width, int height) {
  PerspectiveCamera c;
  c.position = position;
  c.forward = normalize(forward);
  c.right = normalize(right);
  c.up = normalize(up);
  c.width = width;
  c.height = height;
  set_shorter_axis_fov(&c, fov_degrees);
  return c;
}

void apply_camera_options(const SceneLoadOptions& o, bool frame_bounds, int width, int height, Scene* scene) {
  const bool place = o.camera_position.has_value() || frame_bounds;
  // The scene's own camera stays where it is: a target or up vector alone would be ignored.
  if (!place && (o.camera_target || o.camera_up))
    throw Error("--camera-target and --camera-up place the camera together with --camera-pos; give --camera-pos too");
  if (!place && !o.fov_degrees) return;
  const float fov = o.fov_degrees.value_or(kDefaultFov);
  if (!(fov > 0.f && fov < 180.f)) throw Error("--fov must be between 0 and 180 degrees");
  PerspectiveCamera& c = scene->camera;
  const PerspectiveCamera file_camera = c;  // its thin lens and pixel filter survive the override
  if (!place) {  // only the field of view changes
    c = make_file_camera(c.position, c.forward, c.right, c.up, fov, width, height);
    set_thin_lens(&c, file_camera.lens_radius, file_camera.focus_distance);
    c.filter = file_camera.filter;
    return;
  }
  const Bounds3 b = scene->geometry_bounds();
  const BoundingSphere s = b.empty() ? BoundingSphere{Vec3(), 1.f} : bounding_sphere(b);
  const Vec3 target = o.camera_target.value_or(s.center);
  const Vec3 up = o.camera_up.value_or(Vec3(0, 1, 0));
  // Framing: the bounding sphere fits the shorter image axis, seen along -z.
  const float dist = std::max(s.radius, 1e-3f) / std::sin(radians(fov) * 0.5f) * 1.05f;
  const Vec3 pos = o.camera_position.value_or(s.center + Vec3(0, 0, dist));
  const Vec3 forward = target - pos;
  if (!(length(forward) > 0.f)) throw Error("camera position and target coincide");
  const Vec3 right = cross(normalize(forward), normalize(up));
  if (!(length(right) > 1e-6f)) throw Error("camera up vector is parallel to the view direction");
  c = make_file_camera(pos, forward, right, cross(normalize(right), normalize(forward)), fov, width, height);
  set_thin_lens(&c, file_camera.lens_radius, file_camera.focus_distance);
  c.filter = file_camera.filter;
  scene->camera_moves = false;  // a camera placed on the command line stands still
}

bool names_scene_file(const std::string& name) {
  std::error_code ec;
  // Anything on disk that is not a built-in scene's name: the loader then says what is wrong with it
  // (a directory, a FIFO, a device) instead of "unknown scene".
  return is_scene_file(name) || (!find_builtin_scene(name) && std::filesystem::exists(name, ec));
}

bool is_scene_parameter_name(const std::string& name) {
  return !name.empty() &&
         std::all_of(name.begin(), name.end(), [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; });
}

namespace {
// Every error of loading `path` names a file: one raised without a location by code the loaders
// share (the camera framing of apply_camera_options, say) gets the scene file's.
template <typename F>
auto naming_the_file(const std::string& path, F&& load) -> decltype(load()) {
  try {
    return load();
  } catch (const OptionError&) {
    throw;  // a usage error (a bad --fov) stays one
  } catch (const Error& e) {
    if (!e.location().file.empty()) throw;
    throw Error(FileLoc{path}, e.what());
  } catch (const std::bad_alloc&) {
    // A count in a header (PLY elements, glTF accessors, pbrt arrays) that the memory cannot hold.
    throw Error(FileLoc{path}, "out of memory while reading the scene (does a count in the file claim more data than it holds?)");
  } catch (const std::length_error&) {
    throw Error(FileLoc{path}, "a size in the file is beyond what a container can hold");
  }
}

Scene load_scene_file(const std::string& path, const SceneLoadOptions& options, std::vector<std::string>* warnings,
                      SceneFileSettings* settings) {
  require_regular_file(path);  // a directory or FIFO is named as such, whatever its name ends with
  LoadWarnings w(warnings);
  const std::string ext = scene_file_extension(path);
  if (!options.defines.empty() && ext != ".xml")
    w.add(FileLoc{path}, "-D NAME=VALUE sets Mitsuba scene parameters; ignored for this file");
  if (!options.animation.empty() && ext != ".gltf" && ext != ".glb")
    w.add(FileLoc{path}, "--animation chooses a glTF animation; ignored for this file");
  if (ext == ".pbrt") return pbrt::load_pbrt_file(path, options, &w, settings);
  if (ext == ".xml") return mitsuba::load_mitsuba_file(path, options, &w, settings);
  if (ext == ".gltf" || ext == ".glb") return gltf::load_gltf_file(path, options, &w);
  if (ext != ".ply" && ext != ".obj")
    throw Error(FileLoc{path}, "unknown scene file type '" + ext + "' (expected .pbrt, .xml, .gltf, .glb, .ply or .obj)");
  Scene scene;
  scene.name = path;
  if (ext == ".ply") add_ply_mesh(path, &scene);
  else load_obj_into(path, &w, &scene);
  if (scene.triangles.empty()) throw Error(FileLoc{path}, "the file holds no triangles");
  if (scene.lights.empty()) {
    w.add(FileLoc{path}, "no emitters in the file: lit by a uniform white environment (radiance 1)");
    scene.add_environment_light(Rgb(1.f));
  }
  const int width = options.width > 0 ? options.width : kDefaultSize;
  const int height = options.height > 0 ? options.height : kDefaultSize;
  apply_camera_options(options, true, width, height, &scene);
  const Bounds3 b = scene.geometry_bounds();
  scene.ray_epsilon = std::max(1e-4f, 5e-5f * length(b.hi - b.lo));
  scene.finalize();
  return scene;
}
}  // namespace

Scene load_scene(const std::string& path, const SceneLoadOptions& options, std::vector<std::string>* warnings,
                 SceneFileSettings* settings) {
  Scene scene = naming_the_file(path, [&] { return load_scene_file(path, options, warnings, settings); });
  scene.sources.set_fallback(FileLoc{path});  // what no statement's location covers
  return scene;
}

std::function<Scene(double seconds)> load_scene_animation(const std::string& path, const SceneLoadOptions& options,
                                                          std::vector<std::string>* warnings) {
  const std::string ext = scene_file_extension(path);
  if (ext != ".gltf" && ext != ".glb") return {};
  LoadWarnings w(warnings);
  // shared: std::function copies its target
  auto animation = naming_the_file(path, [&] { return std::make_shared<gltf::GltfAnimation>(path, options, &w); });
  if (!animation->animated()) return {};
  return [animation, path](double seconds) {
    Scene frame = naming_the_file(path, [&] { return animation->scene_at(seconds); });
    frame.sources.set_fallback(FileLoc{path});
    return frame;
  };
}

}  // namespace pathspace
