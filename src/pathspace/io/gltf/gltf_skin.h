// glTF skins (vertex skinning, glTF 2.0 sec. 3.7.3): a skinned mesh's vertex v is drawn at
// sum_i w_i * world(joint_i) * inverseBindMatrix_i * v over the four influences of its JOINTS_0 and
// WEIGHTS_0, and the node's own transform does not apply; normals go through the blended matrix's
// inverse transpose. Joint transforms come from the pose being drawn, so animated joints bend the mesh.
#pragma once

#include <string>
#include <vector>

#include "pathspace/io/gltf/gltf_transform.h"

namespace pathspace::gltf {

// world(joint_j) * inverseBindMatrix_j for every joint of skin `skin`, from the world transforms of
// all nodes (indexed by node). Malformed skins (a joint that is no node, an inverseBindMatrices
// accessor of the wrong type or count) are Errors.
std::vector<Affine> joint_matrices(const Context& c, int skin, const std::vector<Affine>& node_world);

// Primitive `p`'s positions (and normals, when not empty), in mesh space, skinned by `joints` into
// world space. A primitive without JOINTS_0 and WEIGHTS_0 is an Error (its node has a skin).
void skin_primitive(const Context& c, const tinygltf::Primitive& p, const std::string& name, const std::vector<Affine>& joints,
                    std::vector<float>* pos, std::vector<float>* nrm);

}  // namespace pathspace::gltf
