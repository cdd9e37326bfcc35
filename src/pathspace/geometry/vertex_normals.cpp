#include "pathspace/geometry/vertex_normals.h"

#include <cmath>

namespace pathspace {

std::vector<Vec3> angle_weighted_vertex_normals(const std::vector<Vec3>& positions, const std::vector<uint32_t>& indices) {
  std::vector<Vec3> sum(positions.size(), Vec3());
  for (size_t t = 0; t + 2 < indices.size(); t += 3) {
    const uint32_t v[3] = {indices[t], indices[t + 1], indices[t + 2]};
    if (v[0] >= positions.size() || v[1] >= positions.size() || v[2] >= positions.size()) continue;
    const Vec3 n = cross(positions[v[1]] - positions[v[0]], positions[v[2]] - positions[v[0]]);
    const float len = length(n);
    if (!(len > 0.f)) continue;
    for (int k = 0; k < 3; ++k) {
      const Vec3 a = positions[v[(k + 1) % 3]] - positions[v[k]], b = positions[v[(k + 2) % 3]] - positions[v[k]];
      const float la = length(a), lb = length(b);
      if (!(la > 0.f && lb > 0.f)) continue;
      const float angle = std::acos(std::fmax(-1.f, std::fmin(1.f, dot(a, b) / (la * lb))));
      sum[v[k]] += n * (angle / len);
    }
  }
  for (Vec3& n : sum) {
    const float len = length(n);
    n = len > 0.f && std::isfinite(len) ? n / len : Vec3();
  }
  return sum;
}

}  // namespace pathspace
