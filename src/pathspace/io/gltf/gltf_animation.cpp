// glTF scenes over time (see gltf_animation.h).
#include "pathspace/io/gltf/gltf_animation.h"

#include <algorithm>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "pathspace/io/gltf/gltf_channels.h"
#include "pathspace/io/gltf/gltf_interpolation.h"
#include "pathspace/io/gltf/gltf_model.h"
#include "pathspace/io/gltf/gltf_scene_walk.h"

namespace pathspace::gltf {

struct GltfAnimation::State {
  tinygltf::Model model;
  std::string path, folder;
  SceneLoadOptions options;
  std::vector<Channel> channels;
  Scene initial;                     // at 0 s
  std::map<int, Surface> surfaces;   // the materials built into `initial`
  bool camera_moves = false;         // the file's camera, placed by its node
  bool white_environment = false;    // no emitters at 0 s

  Context context(LoadWarnings* warnings) const { return Context{model, path, folder, warnings}; }

  // The animated nodes at `seconds`: their own T, R, S with the animated ones replaced, and the
  // morph weights of those whose weights are animated.
  NodePose pose_at(const Context& c, double seconds) const {
    NodePose pose;
    if (channels.empty()) return pose;
    std::vector<std::optional<Trs>> trs(model.nodes.size());
    pose.weights.resize(model.nodes.size());
    for (const Channel& ch : channels) {
      if (ch.property == AnimatedProperty::weights) {
        pose.weights[size_t(ch.node)] = sample_values(ch, seconds);
        continue;
      }
      std::optional<Trs>& t = trs[size_t(ch.node)];
      if (!t) t = node_trs(c, model.nodes[size_t(ch.node)], element("nodes", size_t(ch.node)));
      const std::array<double, 4> v = sample(ch, seconds);
      double* target = ch.property == AnimatedProperty::translation ? t->t : ch.property == AnimatedProperty::rotation ? t->q : t->s;
      std::copy_n(v.begin(), ch.components(), target);
    }
    pose.local.resize(trs.size());
    for (size_t i = 0; i < trs.size(); ++i)
      if (trs[i]) pose.local[i] = trs_affine(*trs[i]);
    return pose;
  }
};

namespace {

// --animation: an index into animations[] or an animation's name; empty: the first.
size_t choose_animation(const Context& c, const tinygltf::Model& model, const std::string& wanted) {
  if (wanted.empty()) return 0;
  std::vector<std::string> names;
  for (size_t i = 0; i < model.animations.size(); ++i) {
    if (model.animations[i].name == wanted) return i;
    names.push_back(std::to_string(i) + " '" + model.animations[i].name + "'");
  }
  if (std::all_of(wanted.begin(), wanted.end(), [](char ch) { return ch >= '0' && ch <= '9'; }) && wanted.size() < 10) {
    const size_t i = size_t(std::stoul(wanted));
    if (i < model.animations.size()) return i;
  }
  std::string list;
  for (const std::string& n : names) list += (list.empty() ? "" : ", ") + n;
  c.fail("--animation " + wanted + ": no such animation (the file has " + list + ")");
}

}  // namespace

GltfAnimation::GltfAnimation(const std::string& path, const SceneLoadOptions& options, LoadWarnings* warnings)
    : state_(std::make_unique<State>()) {
  State& s = *state_;
  s.path = path;
  s.folder = std::filesystem::path(path).parent_path().string();
  s.options = options;
  read_model(path, &s.model, warnings);
  const Context c = s.context(warnings);
  if (!s.model.animations.empty()) {
    const size_t chosen = choose_animation(c, s.model, options.animation);
    s.channels = read_channels(c, chosen);
    if (s.model.animations.size() > 1 && options.animation.empty())
      c.warn("animations[0] ('" + s.model.animations[0].name + "') is played; the other " +
             std::to_string(s.model.animations.size() - 1) + " are not (--animation N or NAME chooses one)");
  } else if (!options.animation.empty()) {
    c.fail("--animation " + options.animation + ": the file has no animations");
  }
  Scene& scene = s.initial;
  scene.name = path;
  Materials materials(c, &scene);
  const CameraNode camera = add_scene_nodes(c, s.pose_at(c, 0.0), &materials, &scene);
  if (scene.triangles.empty()) c.fail("the scene holds no triangles");
  // As glTF viewers do: a file without light sources (KHR_lights_punctual) is lit by an environment,
  // also when some materials emit (a helmet's glowing visor lights nothing around it).
  const size_t emitters = scene.lights.size();
  if (std::all_of(scene.lights.begin(), scene.lights.end(), [](const Light& l) { return is_area_light(l); })) {
    c.warn(emitters == 0 ? std::string("no emitters in the file: lit by a uniform white environment (radiance 1)")
                         : "no light sources in the file (only " + std::to_string(emitters) +
                               " emissive triangles): lit by a uniform white environment (radiance 1) as well, as glTF viewers do");
    scene.add_environment_light(Rgb(1.f));
    s.white_environment = true;
  }
  s.camera_moves = set_camera(c, camera, options, &scene);
  const Bounds3 b = scene.geometry_bounds();
  scene.ray_epsilon = std::max(1e-4f, 5e-5f * length(b.hi - b.lo));
  scene.finalize();
  s.surfaces = materials.built();
}

GltfAnimation::~GltfAnimation() = default;

bool GltfAnimation::animated() const { return !state_->channels.empty(); }
Scene GltfAnimation::initial_scene() && { return std::move(state_->initial); }

Scene GltfAnimation::scene_at(double seconds) const {
  const State& s = *state_;
  LoadWarnings quiet(nullptr);  // the scene at 0 s reported every warning the walk can give
  const Context c = s.context(&quiet);
  Scene scene;
  scene.name = s.path;
  scene.materials = s.initial.materials;
  scene.textures = s.initial.textures;
  Materials materials(c, &scene, s.surfaces);
  const CameraNode camera = add_scene_nodes(c, s.pose_at(c, seconds), &materials, &scene);
  // Decided at 0 s for every frame, so the lighting does not switch when an emitter shrinks to nothing.
  if (s.white_environment) scene.add_environment_light(Rgb(1.f));
  if (s.camera_moves) set_camera(c, camera, s.options, &scene);
  else scene.camera = s.initial.camera;
  scene.ray_epsilon = s.initial.ray_epsilon;
  scene.finalize();
  return scene;
}

}  // namespace pathspace::gltf
