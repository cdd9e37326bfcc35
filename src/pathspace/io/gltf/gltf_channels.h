// glTF animation channels that move nodes (`translation`, `rotation`, `scale`) or blend their meshes'
// morph targets (`weights`), read and checked once
// so that sampling them at any time cannot fail: key times finite, >= 0 and strictly increasing,
// output counts matching the key count (three values per key for CUBICSPLINE), values finite,
// rotation keys non-zero, one weight per morph target of the node's mesh. Malformed data is a
// pathspace::Error naming the file and the element; unknown paths are a warning and the channel is
// skipped.
#pragma once

#include <string>
#include <vector>

#include "pathspace/io/gltf/gltf_context.h"

namespace pathspace::gltf {

enum class AnimatedProperty { translation, rotation, scale, weights };
enum class Interpolation { linear, step, cubic_spline };

struct Channel {
  int node = -1;
  AnimatedProperty property = AnimatedProperty::translation;
  Interpolation interpolation = Interpolation::linear;
  std::vector<double> times;   // seconds, strictly increasing
  std::vector<double> values;  // components() per value; CUBICSPLINE: in-tangent, value, out-tangent per key
  std::string name;            // "animations[0].channels[2]", for messages
  size_t targets = 0;          // weights: the number of morph targets of the node's mesh

  size_t components() const {
    return property == AnimatedProperty::weights ? targets : property == AnimatedProperty::rotation ? 4 : 3;
  }
};

// The node channels of `model.animations[animation]`. A node animated twice by one animation is an
// Error (the glTF spec forbids it), as is a channel on a node that has a `matrix`.
std::vector<Channel> read_channels(const Context& c, size_t animation);

}  // namespace pathspace::gltf
