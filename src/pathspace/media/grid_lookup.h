// Lookups into a grid medium's samples (media/medium.h, GridShape): trilinear interpolation of the
// cell-centred samples, clamped to the edge samples inside the unit cube and zero outside it, as
// pbrt-v4's SampledGrid and Mitsuba 3's gridvolume do; and the map from world to grid space.
#pragma once

#include "pathspace/media/medium.h"
#include "pathspace/math/rgb.h"

namespace pathspace {

PS_INLINE Vec3 grid_point(const Medium& m, const Vec3& p) {
  const float* a = m.world_to_grid;
  return {a[0] * p.x + a[1] * p.y + a[2] * p.z + a[3], a[4] * p.x + a[5] * p.y + a[6] * p.z + a[7],
          a[8] * p.x + a[9] * p.y + a[10] * p.z + a[11]};
}
PS_INLINE Vec3 grid_vector(const Medium& m, const Vec3& d) {
  const float* a = m.world_to_grid;
  return {a[0] * d.x + a[1] * d.y + a[2] * d.z, a[4] * d.x + a[5] * d.y + a[6] * d.z, a[8] * d.x + a[9] * d.y + a[10] * d.z};
}

PS_INLINE bool inside_unit_cube(const Vec3& g) {
  return g.x >= 0.f && g.x <= 1.f && g.y >= 0.f && g.y <= 1.f && g.z >= 0.f && g.z <= 1.f;
}

// The grid's value at grid-space point g (channel c, or channel 0 of a one-channel grid).
PS_INLINE Rgb grid_lookup(const GridShape& s, const float* values, const Vec3& g) {
  if (!inside_unit_cube(g)) return Rgb();
  const float fx = g.x * float(s.nx) - 0.5f, fy = g.y * float(s.ny) - 0.5f, fz = g.z * float(s.nz) - 0.5f;
  const int x0 = int(floorf(fx)), y0 = int(floorf(fy)), z0 = int(floorf(fz));
  const float tx = fx - float(x0), ty = fy - float(y0), tz = fz - float(z0);
  Rgb out;
  for (int corner = 0; corner < 8; ++corner) {
    const int dx = corner & 1, dy = (corner >> 1) & 1, dz = (corner >> 2) & 1;
    const int xi = x0 + dx < 0 ? 0 : (x0 + dx >= int(s.nx) ? int(s.nx) - 1 : x0 + dx);
    const int yi = y0 + dy < 0 ? 0 : (y0 + dy >= int(s.ny) ? int(s.ny) - 1 : y0 + dy);
    const int zi = z0 + dz < 0 ? 0 : (z0 + dz >= int(s.nz) ? int(s.nz) - 1 : z0 + dz);
    const float w = (dx ? tx : 1.f - tx) * (dy ? ty : 1.f - ty) * (dz ? tz : 1.f - tz);
    const float* v = values + s.offset + (size_t(zi) * s.ny * s.nx + size_t(yi) * s.nx + size_t(xi)) * s.channels;
    out += s.channels == 1 ? Rgb(v[0]) * w : Rgb(v[0], v[1], v[2]) * w;
  }
  return out;
}

// sigma_t and albedo of medium m at grid-space point g.
PS_INLINE Rgb medium_sigma_t(const Medium& m, const float* values, const Vec3& g) {
  if (m.type == MediumType::homogeneous) return m.sigma_t;
  return m.sigma_t * grid_lookup(m.density, values, g);
}
PS_INLINE Rgb medium_albedo(const Medium& m, const float* values, const Vec3& g) {
  if (m.type == MediumType::homogeneous || m.albedo_grid.nx == 0) return m.albedo;
  return grid_lookup(m.albedo_grid, values, g);
}

}  // namespace pathspace
