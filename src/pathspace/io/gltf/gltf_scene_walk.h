// The node trees of a glTF scene as scene content: meshes (gltf_meshes.h) and KHR_lights_punctual
// lights placed by their world transforms, and the camera. A pose replaces the local transforms of
// some nodes, so the same walk gives the still scene and an animation's scene at any time.
#pragma once

#include <optional>
#include <vector>

#include "pathspace/io/gltf/gltf_materials.h"
#include "pathspace/io/gltf/gltf_transform.h"
#include "pathspace/io/scene_loader.h"

namespace pathspace::gltf {

// An animation's state of the nodes, indexed by node: an entry replaces the node's own local
// transform, or the morph weights its mesh is drawn with; nullopt (or past the end): its own.
struct NodePose {
  std::vector<std::optional<Affine>> local;
  std::vector<std::optional<std::vector<double>>> weights;
};

// The first camera's node met in the walk (index -1: none) and its world transform.
struct CameraNode {
  int index = -1;
  Affine world;
};

// Adds the meshes and lights of the default scene's node trees (without scenes: of every root node)
// to `scene`, building materials through `materials`. Node cycles, nodes with two parents and
// hierarchies deeper than 1000 levels are Errors.
CameraNode add_scene_nodes(const Context& c, const NodePose& pose, Materials* materials, Scene* scene);

// Sets scene->camera from the walk's camera, then the options' overrides (or frames the bounds when
// the file has no perspective camera). Returns true when the camera is the file's own, placed by its
// node (it then moves with an animated node); false when it frames the bounds or --camera-pos places it.
bool set_camera(const Context& c, const CameraNode& node, const SceneLoadOptions& o, Scene* scene);

}  // namespace pathspace::gltf
