// glTF mesh primitives → scene triangles: POSITION, NORMAL (smooth shading normals) and TEXCOORD_0,
// indexed or not, with morph targets blended by weights, transformed to world space by the node's matrix. Only mode 4 (TRIANGLES) is
// drawn; points, lines, strips and fans are skipped with a warning, as are other attributes.
#pragma once

#include <string>
#include <vector>

#include "pathspace/io/gltf/gltf_materials.h"
#include "pathspace/io/gltf/gltf_transform.h"

namespace pathspace::gltf {

// The number of morph targets of mesh `mesh_index` (0: none): every primitive must have as many, and
// the mesh's `weights`, when given, one per target (an Error otherwise).
size_t morph_target_count(const Context& c, int mesh_index);

// The morph weights a node's mesh is drawn with: the node's `weights`, else the mesh's, else zeros
// (one per target; a count that differs from the targets' is an Error).
std::vector<double> default_morph_weights(const Context& c, const tinygltf::Node& node, const std::string& node_name);

// Appends every primitive of mesh `mesh_index` as placed by `world`, its morph targets' POSITION and
// NORMAL displacements blended in with `weights` (one per target, or empty: none); with `joints`
// (a skinned node's joint matrices, gltf_skin.h) skinned by them instead of placed by `world`.
// Emissive materials make each triangle of positive area an area light.
void add_mesh(const Context& c, int mesh_index, const Affine& world, const std::vector<double>& weights,
              const std::vector<Affine>* joints, Materials* materials, Scene* scene);

}  // namespace pathspace::gltf
