// A ray-surface hit as the integrators see it: position, geometric and shading normal, and what
// is there (material, emitter). Shading normal equals the geometric one until meshes carry normals.
#pragma once

#include <cstdint>

#include "pathspace/geometry/shapes.h"
#include "pathspace/math/frame.h"

namespace pathspace {

struct SurfaceHit {
  Vec3 p;
  Vec3 ng;  // geometric normal (winding / outward sphere normal; one-sided materials use it)
  Vec3 ns;  // shading normal
  float t = kInfinity;
  float u = 0.f, v = 0.f;  // barycentrics (triangles) or parametric coordinates (spheres)
  uint32_t prim = 0;
  ShapeKind kind = ShapeKind::triangle;
  uint32_t material = 0;
  int32_t light = kNoLight;
};

}  // namespace pathspace
