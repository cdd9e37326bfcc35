// glTF mesh primitives → scene triangles: POSITION, NORMAL (smooth shading normals) and TEXCOORD_0,
// indexed or not, transformed to world space by the node's matrix. Only mode 4 (TRIANGLES) is
// drawn; points, lines, strips and fans are skipped with a warning, as are other attributes.
#pragma once

#include "pathspace/io/gltf/gltf_materials.h"
#include "pathspace/io/gltf/gltf_transform.h"

namespace pathspace::gltf {

// Appends every primitive of mesh `mesh_index` as placed by `world`. Emissive materials make each
// triangle of positive area an area light.
void add_mesh(const Context& c, int mesh_index, const Affine& world, Materials* materials, Scene* scene);

}  // namespace pathspace::gltf
