// PLY meshes (Turk's polygon file format): ascii, binary_little_endian and binary_big_endian, plain
// or gzip-compressed. Our own reader because Debian ships no PLY library. Reads vertex positions,
// optional normals and texture coordinates, and face index lists (polygons are fan-triangulated);
// every other element and property is skipped by its declared size. Malformed input is a
// pathspace::Error with the header line or the body's byte offset / element index, never a crash.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "pathspace/math/vec3.h"

namespace pathspace {

struct PlyMesh {
  std::vector<Vec3> positions;
  std::vector<Vec3> normals;               // empty or one per vertex (nx ny nz)
  std::vector<std::array<float, 2>> uvs;   // empty or one per vertex (u v, s t, texture_u texture_v)
  std::vector<uint32_t> indices;           // three per triangle
  size_t polygon_faces = 0;                // input faces with more than 3 vertices (fan-triangulated)
};

// Reads a .ply or .ply.gz file.
PlyMesh read_ply(const std::string& path);
// Parses PLY bytes; `name` is used in error messages.
PlyMesh parse_ply(const std::string& bytes, const std::string& name);

}  // namespace pathspace
