// A unit sphere as triangles, for the spheres that cannot stay analytic (geometry/shapes.h): moving
// ones (spheres do not move, scene/motion.h) and, in Mitsuba files, ellipsoids. Both scene readers
// take this one mesh and map its parameters to their file format's uv convention.
#pragma once

#include <cstdint>
#include <vector>

#include "pathspace/math/vec3.h"
#include "pathspace/sampling/warps.h"

namespace pathspace {

// `segments` around the z axis and segments / 2 rings from pole to pole. Each row of vertices repeats
// its first one at phi = 2 pi, so no triangle's parameters wrap; the pole rows get triangles, not
// degenerate quads: segments * (segments - 2) triangles in all.
struct TessellatedSphere {
  std::vector<Vec3> points;       // on the unit sphere, so also the outward normals
  std::vector<Point2> params;     // (phi / 2 pi, theta / pi) with theta measured from the -z pole
  std::vector<uint32_t> indices;  // counter-clockwise seen from outside
};

TessellatedSphere tessellate_unit_sphere(int segments);

}  // namespace pathspace
