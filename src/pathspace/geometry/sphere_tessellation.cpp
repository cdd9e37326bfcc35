#include "pathspace/geometry/sphere_tessellation.h"

#include <cmath>

namespace pathspace {

TessellatedSphere tessellate_unit_sphere(int segments) {
  TessellatedSphere m;
  const int around = segments, rings = segments / 2;
  // Rows from the -z pole (v = 0) to the +z pole (v = 1).
  for (int j = 0; j <= rings; ++j) {
    const double v = double(j) / rings, theta = M_PI * (1.0 - v);  // theta from +z
    for (int i = 0; i <= around; ++i) {
      const double u = double(i) / around, phi = 2.0 * M_PI * u;
      m.points.push_back(Vec3(float(std::sin(theta) * std::cos(phi)), float(std::sin(theta) * std::sin(phi)), float(std::cos(theta))));
      m.params.push_back(Point2{float(u), float(v)});
    }
  }
  const auto at = [&](int i, int j) { return uint32_t(j * (around + 1) + i); };
  for (int j = 0; j < rings; ++j)
    for (int i = 0; i < around; ++i) {
      // Counter-clockwise seen from outside (u grows eastwards, v northwards).
      if (j > 0) m.indices.insert(m.indices.end(), {at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      if (j + 1 < rings) m.indices.insert(m.indices.end(), {at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  return m;
}

}  // namespace pathspace
