// Sampling a glTF animation channel at a time, as the glTF 2.0 spec defines its interpolations:
// LINEAR (rotations: slerp of unit quaternions along the shorter arc), STEP (the key at or before the
// time) and CUBICSPLINE (cubic Hermite with the keys' in- and out-tangents scaled by the key interval;
// rotations normalised afterwards). Before the first key and after the last the value is clamped.
#pragma once

#include <array>
#include <vector>

#include "pathspace/io/gltf/gltf_channels.h"

namespace pathspace::gltf {

using Quaternion = std::array<double, 4>;  // x, y, z, w

// Unit quaternions a and b interpolated at u in [0, 1] along the shorter of the two arcs.
Quaternion slerp(const Quaternion& a, const Quaternion& b, double u);

// The channel's value at `seconds`: components() numbers (3; 4 for a unit quaternion; one per
// morph target for weights).
std::vector<double> sample_values(const Channel& channel, double seconds);
// The same for a node transform channel, in the first 3 or 4 numbers.
std::array<double, 4> sample(const Channel& channel, double seconds);

}  // namespace pathspace::gltf
