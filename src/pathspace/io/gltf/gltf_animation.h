// A glTF file whose scene can be produced at any time of its animation: node `translation`,
// `rotation` and `scale` channels (gltf_channels.h, sampled by gltf_interpolation.h) move the meshes,
// the KHR_lights_punctual lights and the camera of the animated nodes and their descendants, and
// `weights` channels blend their meshes' morph targets (gltf_meshes.h).
// Only the file's first animation plays: glTF animations are separate clips (a walk, a run) that
// often drive the same nodes, so playing them together would mix them; the others are a warning.
// The file is parsed and checked once; each time re-walks the node trees with the animated local
// transforms, reusing the materials and decoded textures of the scene at t = 0.
#pragma once

#include <memory>
#include <string>

#include "pathspace/io/load_warnings.h"
#include "pathspace/io/scene_loader.h"

namespace pathspace::gltf {

class GltfAnimation {
 public:
  // Reads the file and its animation (SceneLoadOptions::animation, default the first) and builds the
  // scene at t = 0 s; `warnings` gets what
  // that reports (later times report nothing new). Malformed files and animation data are a
  // pathspace::Error naming the file.
  GltfAnimation(const std::string& path, const SceneLoadOptions& options, LoadWarnings* warnings);
  ~GltfAnimation();

  // Whether any node channel moves something (false: every time gives the scene at 0 s).
  bool animated() const;
  // The finalised scene at 0 s, as load_scene returns it, moved out of a temporary GltfAnimation.
  Scene initial_scene() &&;
  // The finalised scene `seconds` into the animation (clamped to its first and last keys). Its camera
  // moves with its node unless --camera-pos placed it or the view frames the bounds (then it is the
  // camera at 0 s, so that a moving object does not move the framing). Ray epsilon and the white
  // environment of a file without emitters are those of 0 s too.
  Scene scene_at(double seconds) const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace pathspace::gltf
