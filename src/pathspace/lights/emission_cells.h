// An area triangle's emission map sampled by its brightness (glTF emissiveTexture, a textured
// emitter): the triangle is cut into n x n sub-triangles of equal area by lines parallel to its
// edges, each weighted by the map's mean luminance over it, and a light sample picks a sub-triangle
// by weight, then a point uniformly inside it. Without cells (n = 0) the triangle is sampled
// uniformly by area, as before. The density is piecewise constant: pmf(cell) * n^2 / area, so next
// event estimation, light paths and every MIS weight that asks for it see the same function of the
// point (scene/light_sampling.h, scene/light_emission.h). The host builds the cells in
// Scene::finalize (scene/emission_cells_build.h).
//
// Cells are numbered in barycentric coordinates (a, c) = (weight of vertex 0, weight of vertex 1)
// scaled by n: cell 2 (j n + i) is the "up" sub-triangle with corners (i, j), (i + 1, j), (i, j + 1),
// cell 2 (j n + i) + 1 the "down" one with corners (i + 1, j + 1), (i, j + 1), (i + 1, j). Cells past
// the triangle's far edge (i + j >= n up, i + j >= n - 1 down) exist with weight 0, so the index is
// plain arithmetic. A light's cells are 2 n^2 probabilities followed by their 2 n^2 + 1 CDF entries.
#pragma once

#include <cstdint>

#include "pathspace/base/platform.h"
#include "pathspace/math/vec3.h"
#include "pathspace/sampling/discrete.h"
#include "pathspace/sampling/warps.h"

namespace pathspace {

PS_INLINE uint32_t emission_cell_count(uint32_t n) { return 2u * n * n; }
// Floats a light with an n x n grid holds: probabilities, then the CDF.
PS_INLINE uint32_t emission_cell_floats(uint32_t n) { return 2u * emission_cell_count(n) + 1u; }

PS_INLINE DiscreteView emission_cell_distribution(const float* cells, uint32_t n) {
  const uint32_t count = emission_cell_count(n);
  return {cells + count, cells, count};
}

// Whether a cell lies inside the triangle (the others have weight 0).
PS_INLINE bool emission_cell_inside(uint32_t n, uint32_t cell) { return (cell / 2u) % n + (cell / 2u) / n + (cell & 1u) < n; }

// The cell holding barycentrics b (b.x of vertex 0, b.y of vertex 1); points a rounding step off the
// triangle go to the nearest cell inside it.
PS_INLINE uint32_t emission_cell_at(uint32_t n, Point2 b) {
  const float a = fminf(fmaxf(b.x, 0.f), 1.f) * float(n), c = fminf(fmaxf(b.y, 0.f), 1.f) * float(n);
  uint32_t i = a < float(n) ? uint32_t(a) : n - 1, j = c < float(n) ? uint32_t(c) : n - 1;
  if (i + j > n - 1) i = n - 1 - j;  // past the far edge by rounding
  const bool down = (a - float(i)) + (c - float(j)) > 1.f && i + j + 1 < n;
  return 2u * (j * n + i) + (down ? 1u : 0u);
}

// The corner `k` (0, 1, 2) of cell `cell` in scaled barycentrics, as (a, c).
PS_INLINE Point2 emission_cell_corner(uint32_t n, uint32_t cell, int k) {
  const float i = float((cell / 2u) % n), j = float((cell / 2u) / n);
  if (cell & 1u) return k == 0 ? Point2{i + 1.f, j + 1.f} : k == 1 ? Point2{i, j + 1.f} : Point2{i + 1.f, j};
  return k == 0 ? Point2{i, j} : k == 1 ? Point2{i + 1.f, j} : Point2{i, j + 1.f};
}

// A point of the triangle by the cells' weights from two uniform numbers; returns its barycentrics
// and writes the area density times the triangle's area (1 for uniform sampling).
PS_INLINE Point2 sample_emission_cells(const float* cells, uint32_t n, Point2 u, float* density_times_area) {
  const DiscreteView d = emission_cell_distribution(cells, n);
  float p = 0.f;
  const uint32_t cell = d.sample(u.x, &p);
  // The CDF step's remainder, reused for the point inside the cell.
  const float ux = fminf(fmaxf((u.x - d.cdf[cell]) / p, 0.f), 0x1.fffffep-1f);
  const Point2 w = square_to_triangle_barycentric({ux, u.y});
  const Point2 c0 = emission_cell_corner(n, cell, 0), c1 = emission_cell_corner(n, cell, 1), c2 = emission_cell_corner(n, cell, 2);
  const float w2 = 1.f - w.x - w.y, inv_n = 1.f / float(n);
  *density_times_area = p * float(n) * float(n);
  return {(c0.x * w.x + c1.x * w.y + c2.x * w2) * inv_n, (c0.y * w.x + c1.y * w.y + c2.y * w2) * inv_n};
}

// The area density times the triangle's area at barycentrics b.
PS_INLINE float emission_cells_density(const float* cells, uint32_t n, Point2 b) {
  return emission_cell_distribution(cells, n).probability(emission_cell_at(n, b)) * float(n) * float(n);
}

// Barycentrics (weight of p0, weight of p1) of a point p on triangle p0 p1 p2.
PS_INLINE Point2 triangle_barycentrics_of(const Vec3& p, const Vec3& p0, const Vec3& p1, const Vec3& p2) {
  const Vec3 e1 = p1 - p0, e2 = p2 - p0, v = p - p0;
  const float d00 = dot(e1, e1), d01 = dot(e1, e2), d11 = dot(e2, e2), d20 = dot(v, e1), d21 = dot(v, e2);
  const float det = d00 * d11 - d01 * d01;
  if (!(det > 0.f)) return {1.f / 3.f, 1.f / 3.f};
  const float b1 = (d11 * d20 - d01 * d21) / det, b2 = (d00 * d21 - d01 * d20) / det;
  return {1.f - b1 - b2, b1};
}

}  // namespace pathspace
