// Participating media as device-safe records (2014 paper sec. 3's "participating media"; pbrt-v4
// ch. 11, Mitsuba 3's homogeneous and heterogeneous media). A medium has an extinction sigma_t and
// a single-scattering albedo (sigma_s = albedo sigma_t), per RGB channel and per unit length, and a
// Henyey-Greenstein phase function (media/henyey_greenstein.h).
//  - homogeneous: sigma_t and albedo everywhere.
//  - grid: sigma_t = sigma_t_scale * grid value (1 or 3 channels, trilinear, zero outside the box)
//    and albedo = the albedo grid (3 channels) or the constant; a coarse grid of per-cell majorants
//    bounds sigma_t for delta and ratio tracking (media/free_flight.h).
// Shapes bind media through a MediumInterface; paths carry the index of the medium they travel in
// (kVacuum: none).
#pragma once

#include <cstdint>

#include "pathspace/math/rgb.h"
#include "pathspace/math/vec3.h"

namespace pathspace {

inline constexpr int32_t kVacuum = -1;

enum class MediumType : uint8_t { homogeneous, grid };

// A grid's cells: nx * ny * nz samples at the cell centres of the unit cube (pbrt-v4's SampledGrid:
// sample (i, j, k) sits at ((i + 0.5) / nx, ...)), `channels` floats each, from `offset` on in
// MediaView::grid_values.
struct GridShape {
  uint32_t nx = 0, ny = 0, nz = 0;
  uint32_t channels = 1;
  uint32_t offset = 0;
};

struct Medium {
  MediumType type = MediumType::homogeneous;
  Rgb sigma_t;          // homogeneous: the extinction; grid: the factor on the grid's values
  Rgb albedo;           // sigma_s / sigma_t (grid: unless an albedo grid is given)
  float g = 0.f;        // Henyey-Greenstein asymmetry

  // grid: world -> the grid's unit cube [0, 1]^3 (an affine map, rows of a 3x4 matrix). Distances
  // along a ray stay world distances: the ray's direction is mapped with the same linear part.
  float world_to_grid[12] = {1.f, 0.f, 0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 0.f, 1.f, 0.f};
  GridShape density;                // the sigma_t grid (1 or 3 channels)
  GridShape albedo_grid;            // 3 channels, or nx == 0 for the constant `albedo`
  GridShape majorants;              // 1 channel: max of sigma_t over each coarse cell of the box
};

// Which media a shape separates (pbrt-v4's MediumInterface, Mitsuba's interior/exterior): the
// inside lies opposite the geometric normal. A shape whose two sides are the same medium is no
// transition: a path crossing it stays in its medium.
struct MediumInterface {
  int32_t inside = kVacuum;
  int32_t outside = kVacuum;
  bool transition = false;
};

PS_INLINE MediumInterface make_medium_interface(int32_t inside, int32_t outside) {
  return {inside, outside, inside != outside};
}

// The medium a ray leaving a surface in direction `d` travels in: the side `d` points to when the
// surface is a transition, else the medium the path was in.
PS_INLINE int32_t medium_after(const MediumInterface& m, const Vec3& ng, const Vec3& d, int32_t current) {
  if (!m.transition) return current;
  return dot(d, ng) < 0.f ? m.inside : m.outside;
}

}  // namespace pathspace
