// Smooth shading normals for a triangle mesh that has none, as Mitsuba 3 computes them for its
// PLY and OBJ shapes (Mesh::recompute_vertex_normals): each vertex takes the mean of the normals of
// the triangles around it, each weighted by the triangle's angle at that vertex (Thürmer and
// Wüthrich 1998), so a vertex's normal does not depend on how the faces around it are split.
#pragma once

#include <cstdint>
#include <vector>

#include "pathspace/math/vec3.h"

namespace pathspace {

// One unit normal per position, on the side of the counter-clockwise winding; a vertex of no
// (non-degenerate) triangle gets the zero vector, which shading treats as flat.
std::vector<Vec3> angle_weighted_vertex_normals(const std::vector<Vec3>& positions, const std::vector<uint32_t>& indices);

}  // namespace pathspace
