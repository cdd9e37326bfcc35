// Cutout opacity (Mitsuba's `mask`, pbrt-v4's shape "alpha"): a triangle whose material has opacity
// a < 1 is hit by the fraction a of the rays that reach it; the others go on as if it were not
// there, for nearest-hit and shadow rays alike, so the image is that of a surface of coverage a.
// Which rays pass is a hash of the ray (origin, direction) and the triangle, as pbrt-v4 hashes the
// ray: a pure function, the same for every thread count, and independent between two cutouts on one
// ray (pbrt-v4 draws one number per ray, so two stacked half-covered leaves let half the rays through
// instead of a quarter). Both ray casters apply it: the Embree backend in a filter function
// (accel/embree_accel.cpp), the device BVH tracer in its triangle test (accel/bvh_tracer.h).
// Emitting triangles and spheres ignore it (scene validation warns).
#pragma once

#include <cstdint>

#include "pathspace/geometry/surface_attributes.h"
#include "pathspace/materials/material.h"
#include "pathspace/math/vec3.h"
#include "pathspace/sampling/hash.h"
#include "pathspace/scene/texture.h"

namespace pathspace {

PS_INLINE bool has_cutout(const Material& m) { return m.opacity < 1.f || m.opacity_texture >= 0; }

// The opacity of triangle `prim`'s material at barycentrics (b1, b2) of vertices 1 and 2; the
// texture's first channel (loaders store a scalar texture in all three).
PS_INLINE float triangle_opacity(const Triangle& tri, const Material& m, const Point2* uvs, const TextureView* textures,
                                 float b1, float b2) {
  if (m.opacity_texture < 0) return m.opacity;
  return m.opacity * texture_lookup(textures[m.opacity_texture], triangle_uv(tri, uvs, b1, b2)).r;
}

// Whether the ray (o, d) passes through triangle `prim` at barycentrics (b1, b2) instead of hitting it.
// Out of line on the GPU: called from the BVH's triangle test, only in scenes with cutouts.
PS_INLINE_HOST_ONLY bool ray_passes_cutout(const Triangle* triangles, const Material* materials, const Point2* uvs,
                                           const TextureView* textures, uint32_t prim, float b1, float b2,
                                           const Vec3& o, const Vec3& d) {
  const Triangle& tri = triangles[prim];
  const Material& m = materials[tri.material];
  if (!has_cutout(m) || tri.light != kNoLight) return false;
  const float a = triangle_opacity(tri, m, uvs, textures, b1, b2);
  if (!(a < 1.f)) return false;  // NaN counts as opaque (validation rejects NaN opacity)
  if (a <= 0.f) return true;
  uint64_t h = hash_combine(float_bits(o.x), float_bits(o.y));
  h = hash_combine(h, float_bits(o.z));
  h = hash_combine(h, float_bits(d.x));
  h = hash_combine(h, float_bits(d.y));
  h = hash_combine(h, float_bits(d.z));
  return bits_to_unit_float(hash_combine(h, prim)) >= a;
}

}  // namespace pathspace
