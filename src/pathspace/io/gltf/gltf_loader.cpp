// glTF scene loading (see gltf_loader.h): parse with tinygltf, walk the default scene's node trees,
// then camera, lights and finalize. Without a camera the view frames the bounds as for OBJ; without
// emitters a white environment lights the scene (warning), as for OBJ and PLY.
#include "pathspace/io/gltf/gltf_loader.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <set>
#include <sstream>

#include "pathspace/io/file_bytes.h"
#include "pathspace/io/gltf/gltf_meshes.h"

namespace pathspace::gltf {

namespace {

constexpr int kDefaultHeight = 512;
constexpr int kMaxDepth = 1000;  // recursion bound: real hierarchies are far shallower

// tinygltf image callback: keep the encoded bytes; io/image_io decodes them per material slot. A
// bufferView image is passed as &buffer[byteOffset] with byteLength unchecked by tinygltf, so the
// range is checked here before any byte is read.
bool keep_image_bytes(tinygltf::Image* image, const int index, std::string* err, std::string*, int, int, const unsigned char* bytes,
                      int size, void* user) {
  const auto* model = static_cast<const tinygltf::Model*>(user);
  if (image->bufferView >= 0) {
    const tinygltf::BufferView& v = model->bufferViews.at(size_t(image->bufferView));
    const size_t have = model->buffers.at(size_t(v.buffer)).data.size();
    if (v.byteOffset > have || v.byteLength > have - v.byteOffset) {
      if (err) *err += "images[" + std::to_string(index) + "]: its bufferView lies outside its buffer\n";
      return false;
    }
  }
  if (size < 0) return false;
  image->image.assign(bytes, bytes + size);
  image->as_is = true;
  return true;
}

void parse(const std::string& path, tinygltf::Model* model, LoadWarnings* w) {
  const std::string bytes = read_file_bytes(path);
  tinygltf::TinyGLTF loader;
  loader.SetImageLoader(keep_image_bytes, model);
  std::string err, warn;
  const std::string folder = std::filesystem::path(path).parent_path().string();
  const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
  const bool ok = bytes.size() >= 4 && bytes.compare(0, 4, "glTF") == 0
                      ? loader.LoadBinaryFromMemory(model, &err, &warn, data, unsigned(std::min<size_t>(bytes.size(), UINT32_MAX)), folder)
                      : loader.LoadASCIIFromString(model, &err, &warn, bytes.data(), unsigned(std::min<size_t>(bytes.size(), UINT32_MAX)), folder);
  std::string line;
  for (std::istringstream ws(warn); std::getline(ws, line);)
    if (!line.empty()) w->add(FileLoc{path}, "tinygltf: " + line);
  if (!ok || !err.empty()) {
    while (!err.empty() && err.back() == '\n') err.pop_back();
    throw Error(FileLoc{path}, "cannot read glTF: " + (err.empty() ? std::string("parse failed") : err));
  }
}

void check_extensions(const Context& c) {
  static const std::set<std::string> kSupported = {"KHR_lights_punctual", "KHR_materials_emissive_strength", "KHR_materials_transmission",
                                                   "KHR_materials_ior"};
  for (const std::string& e : c.model.extensionsRequired)
    if (!kSupported.count(e)) c.fail("extensionsRequired: " + e + " is not supported");
  for (const std::string& e : c.model.extensionsUsed)
    if (!kSupported.count(e)) c.warn("extensionsUsed: " + e + " is not supported; ignored");
}

class SceneWalk {
 public:
  SceneWalk(const Context& c, Scene* scene) : c_(c), scene_(scene), materials_(c, scene), visited_(c.model.nodes.size(), false) {}

  void node(int index, const Affine& parent, const std::string& referrer, int depth = 0) {
    const tinygltf::Model& m = c_.model;
    check_index(c_, index, m.nodes.size(), referrer);
    if (depth > kMaxDepth) c_.fail(referrer + ": node hierarchy deeper than " + std::to_string(kMaxDepth) + " levels");
    // glTF nodes form trees: a node reached twice (two parents, or a cycle) is malformed.
    if (visited_[size_t(index)]) c_.fail(element("nodes", size_t(index)) + " is reached twice (node hierarchies must be trees)");
    visited_[size_t(index)] = true;
    const std::string name = element("nodes", size_t(index));
    const tinygltf::Node& n = m.nodes[size_t(index)];
    const Affine world = parent * local_transform(c_, n, name);
    if (n.skin >= 0) c_.warn(name + ".skin ignored; the mesh is drawn as stored (bind pose)");
    if (n.mesh >= 0) {
      check_index(c_, n.mesh, m.meshes.size(), name + ".mesh");
      add_mesh(c_, n.mesh, world, &materials_, scene_);
    }
    if (n.camera >= 0) {
      check_index(c_, n.camera, m.cameras.size(), name + ".camera");
      if (camera_node_ < 0) {
        camera_node_ = index;
        camera_world_ = world;
      }
    }
    if (const auto it = n.extensions.find("KHR_lights_punctual"); it != n.extensions.end()) light(it->second, world, name);
    for (size_t i = 0; i < n.children.size(); ++i) node(n.children[i], world, name + "." + element("children", i), depth + 1);
  }

  int camera_node() const { return camera_node_; }
  const Affine& camera_world() const { return camera_world_; }
  const std::vector<bool>& visited() const { return visited_; }

 private:
  void light(const tinygltf::Value& ext, const Affine& world, const std::string& node_name) {
    const std::string what = node_name + ".extensions.KHR_lights_punctual.light";
    if (!ext.IsObject() || !ext.Has("light") || !ext.Get("light").IsInt()) c_.fail(what + " is missing or not an integer");
    const int index = ext.Get("light").GetNumberAsInt();
    check_index(c_, index, c_.model.lights.size(), what);
    const tinygltf::Light& l = c_.model.lights[size_t(index)];
    const std::string name = "KHR_lights_punctual." + element("lights", size_t(index));
    Rgb color(1.f);
    if (!l.color.empty()) {
      if (l.color.size() != 3) c_.fail(name + ".color must have 3 numbers");
      color = Rgb(float(l.color[0]), float(l.color[1]), float(l.color[2]));
    }
    const Rgb value = color * float(l.intensity);
    if (!all_finite(value) || !(std::min({value.r, value.g, value.b}) >= 0.f)) c_.fail(name + ": color * intensity is negative or not finite");
    if (l.range > 0.0) c_.warn(name + ".range ignored (no cutoff distance)");
    const Vec3 position = world.point(Vec3());
    if (l.type == "point") {
      scene_->add_point_light(position, value);  // candela taken as our intensity unit
    } else if (l.type == "spot") {
      // Along the node's -z; full intensity inside innerConeAngle, nothing beyond outerConeAngle. The
      // spec's suggested fade (squared, linear in the cosine) becomes pbrt-v4's smoothstep in the cosine.
      const double inner = l.spot.innerConeAngle, outer = l.spot.outerConeAngle;
      if (!(outer > 0.0 && outer <= M_PI / 2) || !(inner >= 0.0 && inner < outer))
        c_.fail(name + ".spot: need 0 <= innerConeAngle < outerConeAngle <= pi/2");
      const Vec3 d = world.vector(Vec3(0, 0, -1));
      if (!(length(d) > 0.f) || !all_finite(d)) c_.fail(name + ": its node's transform collapses the light direction");
      c_.warn(name + ": spot falloff approximated by pbrt-v4's smoothstep in the cosine");
      scene_->add_spot_light(position, d, value, float(std::cos(outer)), float(std::cos(inner)));
    } else if (l.type == "directional") {
      const Vec3 d = world.vector(Vec3(0, 0, -1));  // lights shine along their node's -z
      if (!(length(d) > 0.f) || !all_finite(d)) c_.fail(name + ": its node's transform collapses the light direction");
      scene_->add_directional_light(normalize(d), value);  // lux taken as our irradiance unit
    } else {
      c_.warn(name + ".type '" + l.type + "' not supported; light skipped");
    }
  }

  const Context& c_;
  Scene* scene_;
  Materials materials_;
  std::vector<bool> visited_;
  int camera_node_ = -1;
  Affine camera_world_;
};

// The first camera met in the walk (depth first, children in order), looking down its node's -z with
// +y up. Resolution: the options', else 512 rows and the camera's aspectRatio (square without one).
void set_camera(const Context& c, const SceneWalk& walk, const SceneLoadOptions& o, Scene* scene) {
  int width = o.width, height = o.height;
  const tinygltf::Camera* cam = nullptr;
  if (walk.camera_node() >= 0) {
    cam = &c.model.cameras[size_t(c.model.nodes[size_t(walk.camera_node())].camera)];
    if (cam->type != "perspective") {
      c.warn(element("cameras", size_t(c.model.nodes[size_t(walk.camera_node())].camera)) + ": camera type '" + cam->type +
             "' not supported; the view frames the scene instead");
      cam = nullptr;
    }
  }
  const double aspect = cam ? cam->perspective.aspectRatio : 0.0;
  if (width <= 0 || height <= 0) {
    height = kDefaultHeight;
    width = aspect > 0.0 && std::isfinite(aspect) ? int(std::lround(std::clamp(aspect, 1.0 / 64.0, 64.0) * kDefaultHeight)) : kDefaultHeight;
  }
  if (!cam) {
    apply_camera_options(o, true, width, height, scene);
    return;
  }
  const std::string name = element("cameras", size_t(c.model.nodes[size_t(walk.camera_node())].camera));
  const double yfov = cam->perspective.yfov;
  if (!(yfov > 0.0 && yfov < 3.14159265358979)) c.fail(name + ".perspective.yfov must be between 0 and pi radians");
  const Affine& m = walk.camera_world();
  const Vec3 forward = m.vector(Vec3(0, 0, -1)), up = m.vector(Vec3(0, 1, 0));
  const Vec3 right = cross(forward, up);
  if (!(length(right) > 0.f) || !all_finite(right)) c.fail(name + ": its node's transform is degenerate");
  PerspectiveCamera& pc = scene->camera;
  pc = make_file_camera(m.point(Vec3()), forward, right, cross(normalize(right), normalize(forward)), 90.f, width, height);
  pc.tan_y = float(std::tan(yfov * 0.5));  // yfov is vertical whatever the image's aspect
  pc.tan_x = pc.tan_y * float(width) / float(height);
  apply_camera_options(o, false, width, height, scene);
}

}  // namespace

Scene load_gltf_file(const std::string& path, const SceneLoadOptions& options, LoadWarnings* warnings) {
  tinygltf::Model model;
  parse(path, &model, warnings);
  const Context c{model, path, std::filesystem::path(path).parent_path().string(), warnings};
  check_extensions(c);
  Scene scene;
  scene.name = path;
  SceneWalk walk(c, &scene);
  if (!model.scenes.empty()) {
    const int s = model.defaultScene >= 0 ? model.defaultScene : 0;
    check_index(c, s, model.scenes.size(), "scene");
    if (model.scenes.size() > 1) c.warn("only " + element("scenes", size_t(s)) + " of " + std::to_string(model.scenes.size()) + " scenes is loaded");
    const std::vector<int>& roots = model.scenes[size_t(s)].nodes;
    for (size_t i = 0; i < roots.size(); ++i) walk.node(roots[i], Affine(), element("scenes", size_t(s)) + "." + element("nodes", i));
  } else {  // no scene: every node that is nobody's child is a root
    std::vector<bool> child(model.nodes.size(), false);
    for (const tinygltf::Node& n : model.nodes)
      for (int k : n.children)
        if (k >= 0 && size_t(k) < child.size()) child[size_t(k)] = true;
    if (!model.nodes.empty()) c.warn("no scenes defined; every root node is loaded");
    for (size_t i = 0; i < model.nodes.size(); ++i)
      if (!child[i]) walk.node(int(i), Affine(), element("nodes", i));
  }
  if (!model.animations.empty()) c.warn("animations ignored (" + std::to_string(model.animations.size()) + ")");
  if (scene.triangles.empty()) c.fail("the scene holds no triangles");
  if (scene.lights.empty()) {
    c.warn("no emitters in the file: lit by a uniform white environment (radiance 1)");
    scene.add_environment_light(Rgb(1.f));
  }
  set_camera(c, walk, options, &scene);
  const Bounds3 b = scene.geometry_bounds();
  scene.ray_epsilon = std::max(1e-4f, 5e-5f * length(b.hi - b.lo));
  scene.finalize();
  return scene;
}

}  // namespace pathspace::gltf
