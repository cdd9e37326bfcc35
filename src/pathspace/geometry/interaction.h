// A ray-surface hit as the integrators see it: position, geometric and shading normal, and what
// is there (material, emitter), and the texture coordinates. The shading normal is the interpolated
// vertex normal on meshes that carry normals, else the geometric one.
#pragma once

#include <cstdint>

#include "pathspace/geometry/shapes.h"
#include "pathspace/math/frame.h"
#include "pathspace/sampling/warps.h"

namespace pathspace {

struct SurfaceHit {
  Vec3 p;
  Vec3 ng;  // geometric normal (winding / outward sphere normal; one-sided materials use it)
  Vec3 ns;  // shading normal
  float t = kInfinity;
  float u = 0.f, v = 0.f;  // barycentrics of vertices 1 and 2 (triangles); 0 on spheres
  Point2 uv;               // texture coordinates (vertex uvs or spherical); (0, 0) in scenes without textures
  uint32_t prim = 0;
  ShapeKind kind = ShapeKind::triangle;
  uint32_t material = 0;
  int32_t light = kNoLight;
  float time = 0.f;  // the ray's time (geometry/ray.h): rays leaving the hit inherit it
};

}  // namespace pathspace
