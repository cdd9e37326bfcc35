// glTF node trees to scene content (see gltf_scene_walk.h). Depth first, children in order, so the
// triangles, lights and the first camera come out in the same order for every pose.
#include "pathspace/io/gltf/gltf_scene_walk.h"

#include <algorithm>
#include <cmath>

#include "pathspace/io/gltf/gltf_meshes.h"
#include "pathspace/io/gltf/gltf_skin.h"

namespace pathspace::gltf {

namespace {

constexpr int kDefaultHeight = 512;
constexpr int kMaxDepth = 1000;  // recursion bound: real hierarchies are far shallower

// Which meshes a walk adds: all of them, or (for an animation, whose frames reuse the acceleration
// structure of what does not move) first those of nodes that do not move, then those that do.
enum class Part { all, still, moving };

// The world transform of every node under `pose` (a node in no tree, or below a malformed one, keeps
// the identity: the walk itself reports malformed trees). Skins need their joints' transforms before
// the walk reaches them.
std::vector<Affine> world_transforms(const Context& c, const NodePose& pose) {
  const std::vector<tinygltf::Node>& nodes = c.model.nodes;
  std::vector<Affine> world(nodes.size());
  std::vector<bool> child(nodes.size(), false), done(nodes.size(), false);
  for (const tinygltf::Node& n : nodes)
    for (int k : n.children)
      if (k >= 0 && size_t(k) < nodes.size()) child[size_t(k)] = true;
  std::vector<std::pair<int, Affine>> stack;
  for (size_t i = 0; i < nodes.size(); ++i)
    if (!child[i]) stack.push_back({int(i), Affine()});
  while (!stack.empty()) {
    const auto [index, parent] = stack.back();
    stack.pop_back();
    if (done[size_t(index)]) continue;  // reached twice: malformed, reported by the walk
    done[size_t(index)] = true;
    const tinygltf::Node& n = nodes[size_t(index)];
    const bool posed = size_t(index) < pose.local.size() && pose.local[size_t(index)].has_value();
    world[size_t(index)] = parent * (posed ? *pose.local[size_t(index)] : local_transform(c, n, element("nodes", size_t(index))));
    for (int k : n.children)
      if (k >= 0 && size_t(k) < nodes.size()) stack.push_back({k, world[size_t(index)]});
  }
  return world;
}

class SceneWalk {
 public:
  // `world`: every node's world transform under `pose` (world_transforms), which skins need; empty
  // when the file has none.
  SceneWalk(const Context& c, const NodePose& pose, const std::vector<Affine>& world, Materials* materials, Scene* scene,
            Part part = Part::all)
      : c_(c), pose_(pose), world_(world), scene_(scene), materials_(materials), visited_(c.model.nodes.size(), false), part_(part) {
    animated_ = std::any_of(pose.local.begin(), pose.local.end(), [](const auto& p) { return p.has_value(); });
  }

  void node(int index, const Affine& parent, const std::string& referrer, int depth = 0, bool parent_moves = false) {
    const tinygltf::Model& m = c_.model;
    check_index(c_, index, m.nodes.size(), referrer);
    if (depth > kMaxDepth) c_.fail(referrer + ": node hierarchy deeper than " + std::to_string(kMaxDepth) + " levels");
    // glTF nodes form trees: a node reached twice (two parents, or a cycle) is malformed.
    if (visited_[size_t(index)]) c_.fail(element("nodes", size_t(index)) + " is reached twice (node hierarchies must be trees)");
    visited_[size_t(index)] = true;
    const std::string name = element("nodes", size_t(index));
    const tinygltf::Node& n = m.nodes[size_t(index)];
    const bool posed = size_t(index) < pose_.local.size() && pose_.local[size_t(index)].has_value();
    const bool morphed = size_t(index) < pose_.weights.size() && pose_.weights[size_t(index)].has_value();
    const bool moves = parent_moves || posed || morphed;  // an animated node, or below one
    const Affine world = parent * (posed ? *pose_.local[size_t(index)] : local_transform(c_, n, name));
    // A skinned mesh follows its joints, wherever they are in the trees: it moves whenever any node does.
    const bool skinned = n.skin >= 0 && n.mesh >= 0;
    const bool mesh_moves = moves || (skinned && animated_);
    if (n.mesh >= 0 && (part_ == Part::all || (part_ == Part::moving) == mesh_moves)) {
      check_index(c_, n.mesh, m.meshes.size(), name + ".mesh");
      std::vector<Affine> joints;
      if (skinned) joints = joint_matrices(c_, n.skin, world_);
      add_mesh(c_, n.mesh, world, morphed ? *pose_.weights[size_t(index)] : default_morph_weights(c_, n, name), skinned ? &joints : nullptr,
               materials_, scene_);
    }
    if (part_ == Part::moving) {  // lights and the camera were placed by the walk of the still part
      for (size_t i = 0; i < n.children.size(); ++i) node(n.children[i], world, name + "." + element("children", i), depth + 1, moves);
      return;
    }
    if (n.camera >= 0) {
      check_index(c_, n.camera, m.cameras.size(), name + ".camera");
      if (camera_node_ < 0) {
        camera_node_ = index;
        camera_world_ = world;
      }
    }
    if (const auto it = n.extensions.find("KHR_lights_punctual"); it != n.extensions.end()) light(it->second, world, name);
    for (size_t i = 0; i < n.children.size(); ++i) node(n.children[i], world, name + "." + element("children", i), depth + 1, moves);
  }

  CameraNode camera() const { return {camera_node_, camera_world_}; }

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
  const NodePose& pose_;
  const std::vector<Affine>& world_;  // of every node, when the file has skins
  bool animated_ = false;      // some node's transform is replaced by the pose
  Scene* scene_;
  Materials* materials_;
  std::vector<bool> visited_;
  int camera_node_ = -1;
  Affine camera_world_;
  Part part_;
};

// Walks the roots of the default scene (or every root node) with `walk`.
void walk_roots(const Context& c, SceneWalk& walk, bool report) {
  if (!c.model.scenes.empty()) {
    const int s = c.model.defaultScene >= 0 ? c.model.defaultScene : 0;
    check_index(c, s, c.model.scenes.size(), "scene");
    if (report && c.model.scenes.size() > 1) c.warn("only " + element("scenes", size_t(s)) + " of " + std::to_string(c.model.scenes.size()) + " scenes is loaded");
    const std::vector<int>& roots = c.model.scenes[size_t(s)].nodes;
    for (size_t i = 0; i < roots.size(); ++i) walk.node(roots[i], Affine(), element("scenes", size_t(s)) + "." + element("nodes", i));
  } else {  // no scene: every node that is nobody's child is a root
    std::vector<bool> child(c.model.nodes.size(), false);
    for (const tinygltf::Node& n : c.model.nodes)
      for (int k : n.children)
        if (k >= 0 && size_t(k) < child.size()) child[size_t(k)] = true;
    if (report && !c.model.nodes.empty()) c.warn("no scenes defined; every root node is loaded");
    for (size_t i = 0; i < c.model.nodes.size(); ++i)
      if (!child[i]) walk.node(int(i), Affine(), element("nodes", i));
  }
}

}  // namespace

CameraNode add_scene_nodes(const Context& c, const NodePose& pose, Materials* materials, Scene* scene) {
  const bool animated = std::any_of(pose.local.begin(), pose.local.end(), [](const auto& p) { return p.has_value(); }) ||
                        std::any_of(pose.weights.begin(), pose.weights.end(), [](const auto& w) { return w.has_value(); });
  // Skins read their joints' world transforms: computed once for both walks below.
  const std::vector<Affine> world = c.model.skins.empty() ? std::vector<Affine>() : world_transforms(c, pose);
  if (!animated) {  // a still file: one walk, in the file's order
    SceneWalk walk(c, pose, world, materials, scene);
    walk_roots(c, walk, true);
    return walk.camera();
  }
  // The meshes of nodes that do not move first, those that do after them (Scene::first_moving_triangle).
  SceneWalk still(c, pose, world, materials, scene, Part::still);
  walk_roots(c, still, true);
  scene->first_moving_triangle = uint32_t(scene->triangles.size());
  SceneWalk moving(c, pose, world, materials, scene, Part::moving);
  walk_roots(c, moving, false);
  return still.camera();
}

// The first camera met in the walk (depth first, children in order), looking down its node's -z with
// +y up. Resolution: the options', else 512 rows and the camera's aspectRatio (square without one).
bool set_camera(const Context& c, const CameraNode& node, const SceneLoadOptions& o, Scene* scene) {
  int width = o.width, height = o.height;
  const tinygltf::Camera* cam = nullptr;
  if (node.index >= 0) {
    cam = &c.model.cameras[size_t(c.model.nodes[size_t(node.index)].camera)];
    if (cam->type != "perspective") {
      c.warn(element("cameras", size_t(c.model.nodes[size_t(node.index)].camera)) + ": camera type '" + cam->type +
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
    return false;
  }
  const std::string name = element("cameras", size_t(c.model.nodes[size_t(node.index)].camera));
  const double yfov = cam->perspective.yfov;
  if (!(yfov > 0.0 && yfov < 3.14159265358979)) c.fail(name + ".perspective.yfov must be between 0 and pi radians");
  const Affine& m = node.world;
  const Vec3 forward = m.vector(Vec3(0, 0, -1)), up = m.vector(Vec3(0, 1, 0));
  const Vec3 right = cross(forward, up);
  if (!(length(right) > 0.f) || !all_finite(right)) c.fail(name + ": its node's transform is degenerate");
  PerspectiveCamera& pc = scene->camera;
  pc = make_file_camera(m.point(Vec3()), forward, right, cross(normalize(right), normalize(forward)), 90.f, width, height);
  pc.tan_y = float(std::tan(yfov * 0.5));  // yfov is vertical whatever the image's aspect
  pc.tan_x = pc.tan_y * float(width) / float(height);
  apply_camera_options(o, false, width, height, scene);
  return !o.camera_position.has_value();
}


}  // namespace pathspace::gltf
