// pbrt-v4 shapes that pathspace renders as triangle meshes (pbrt-v4 "Shapes"): `disk` (a ring of
// triangles whose area equals the disk's), `bilinearmesh` (each bilinear patch split into two
// triangles, exact for planar patches) and `loopsubdiv` (subdivided to its level, on the limit surface). The meshes are in object space; the scene builder
// transforms and orients them like any trianglemesh.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "pathspace/io/load_warnings.h"
#include "pathspace/io/pbrt/pbrt_statement.h"
#include "pathspace/math/vec3.h"

namespace pathspace::pbrt {

struct ObjectMesh {
  std::vector<Vec3> positions, normals;  // normals: empty or one per position
  std::vector<std::array<float, 2>> uvs;  // empty or one per position
  std::vector<uint32_t> indices;
};

// Segments around a full disk (a partial one, phimax < 360, gets a proportional share).
inline constexpr int kDiskSegments = 64;

ObjectMesh disk_mesh(const Statement& st, LoadWarnings* warnings);
ObjectMesh bilinear_mesh(const Statement& st, LoadWarnings* warnings);
// `loopsubdiv` ("levels", default 3): Loop subdivision pushed to the limit surface, with smooth
// normals (geometry/loop_subdivision.h).
ObjectMesh loop_subdivision_mesh(const Statement& st);
// A sphere of `radius` about the origin as kSphereSegments x kSphereSegments / 2 quads (triangles at
// the poles), with its normals and pbrt-v4's uvs (u = phi / 2 pi, v = 0 at the -z pole): how a
// moving sphere is rendered, since spheres do not move (scene/motion.h).
inline constexpr int kSphereSegments = 64;
ObjectMesh sphere_mesh(float radius);

}  // namespace pathspace::pbrt
