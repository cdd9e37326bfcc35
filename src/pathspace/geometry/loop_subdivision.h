// Loop subdivision of a triangle mesh (Loop 1987; Warren's weights, as pbrt-v4's `loopsubdiv`):
// each level splits every triangle into four, moves the old vertices by the even masks and places
// the new edge vertices by the odd masks, then the last level's vertices are pushed to the limit
// surface. Boundaries (edges of one triangle) follow the cubic B-spline curve rules, so a mesh with
// holes or borders keeps them, and a planar mesh stays planar.
//   even, interior of valence n: (1 - n b) v + b sum(neighbours), b = 3/16 (n = 3) or 3/(8n)
//   even, boundary:              3/4 v + 1/8 (the two boundary neighbours)
//   odd, interior edge (a, b):   3/8 (a + b) + 1/8 (the two opposite vertices)
//   odd, boundary edge:          1/2 (a + b)
//   limit, interior:             (1 - n x) v + x sum(neighbours), x = 1 / (n + 3 / (8 b))
//   limit, boundary:             2/3 v + 1/6 (the two boundary neighbours)
// Vertices where more than two boundary edges meet (two fans touching) stay where they are.
// Normals are the area-weighted normals of the limit mesh's triangles at each vertex.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "pathspace/math/vec3.h"

namespace pathspace {

struct SubdividedMesh {
  std::vector<Vec3> positions, normals;  // one normal per position
  std::vector<uint32_t> indices;         // three per triangle, the input's orientation
};

// The most triangles loop_subdivide produces (levels are refused beyond it).
// 4M triangles: about 3 s and 0.6 GB here (a file of a few bytes must not ask for more).
inline constexpr uint64_t kMaxSubdividedTriangles = uint64_t(1) << 22;

// Throws pathspace::Error for an index out of range, a degenerate input (no triangle), an edge shared
// by more than two triangles, or a result above kMaxSubdividedTriangles.
SubdividedMesh loop_subdivide(const std::vector<Vec3>& positions, const std::vector<uint32_t>& indices, int levels);

}  // namespace pathspace
