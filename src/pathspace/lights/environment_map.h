// Image environment maps as kernels see them: texels, the direction <-> (u, v) mapping, the
// light-to-world rotation and the importance-sampling distribution (device-safe).
//
// (u, v) in [0,1)^2, v = 0 is the TOP row of the image (texel (i, j) covers
// [i/W, (i+1)/W) x [j/H, (j+1)/H)). Directions are in the map's local frame; world = x*axis_x +
// y*axis_y + z*axis_z. Mappings (docs/conventions.md, "Environment maps"):
//   lat_long   (Mitsuba envmap): phi = 2 pi u, theta = pi v, local y up,
//              d = (sin phi sin theta, cos theta, -cos phi sin theta); bilinear lookup, u wraps.
//   equal_area (pbrt-v4 "infinite" with a square image): Clarberg's equal-area octahedral square,
//              local z up; nearest-texel lookup as pbrt-v4's ImageInfiniteLight.
// Sampling: the distribution's cells are the texels; solid-angle pdf = pdf_uv / (2 pi^2 sin theta)
// (lat_long) or pdf_uv / (4 pi) (equal_area).
#pragma once

#include <cstdint>

#include "pathspace/math/rgb.h"
#include "pathspace/math/vec3.h"
#include "pathspace/sampling/piecewise_2d.h"

namespace pathspace {

enum class EnvironmentMapping : uint8_t { lat_long, equal_area };

struct EnvironmentMapView {
  const Rgb* texels = nullptr;  // width * height, row 0 at the top; nullptr: no image
  int32_t width = 0, height = 0;
  EnvironmentMapping mapping = EnvironmentMapping::lat_long;
  Vec3 axis_x{1.f, 0.f, 0.f}, axis_y{0.f, 1.f, 0.f}, axis_z{0.f, 0.f, 1.f};  // orthonormal
  Piecewise2DView distribution;
  float max_texel = 0.f;  // largest texel component (a bound for photon powers)
};

namespace envmap_detail {
PS_INLINE float wrap01(float s) {
  if (!(fabsf(s) < 1e7f)) return 0.f;
  const float f = s - floorf(s);
  return f < 1.f ? f : 0.f;
}
PS_INLINE float clamp01(float s) { return s > 0.f ? (s < 0.99999994f ? s : 0.99999994f) : 0.f; }
}  // namespace envmap_detail

PS_INLINE Vec3 envmap_uv_to_direction(EnvironmentMapping m, Point2 uv) {
  if (m == EnvironmentMapping::lat_long) {
    const float phi = 2.f * kPi * uv.x, theta = kPi * uv.y;
    const float st = sinf(theta);
    return {sinf(phi) * st, cosf(theta), -cosf(phi) * st};
  }
  // Equal-area octahedral square -> sphere: |u'| + |v'| = r in the z >= 0 half, 2 - r below.
  const float up = 2.f * uv.x - 1.f, vp = 2.f * uv.y - 1.f;
  const float a = fabsf(up), b = fabsf(vp);
  const float signed_d = 1.f - (a + b);
  const float r = 1.f - fabsf(signed_d);
  const float phi = (r == 0.f ? 1.f : (b - a) / r + 1.f) * (kPi / 4.f);
  const float z = copysignf(1.f - r * r, signed_d);
  const float s = r * sqrtf(fmaxf(0.f, 2.f - r * r));
  return {copysignf(cosf(phi), up) * s, copysignf(sinf(phi), vp) * s, z};
}

PS_INLINE Point2 envmap_direction_to_uv(EnvironmentMapping m, const Vec3& d) {
  using namespace envmap_detail;
  if (m == EnvironmentMapping::lat_long) {
    const float u = wrap01(atan2f(d.x, -d.z) * kInvTwoPi);
    return {u, clamp01(acosf(fminf(1.f, fmaxf(-1.f, d.y))) * kInvPi)};
  }
  const float r = sqrtf(fmaxf(0.f, 1.f - fabsf(d.z)));
  const float p = atan2f(fabsf(d.y), fabsf(d.x)) * (2.f / kPi);  // phi / (pi/2) in [0, 1]
  float b = r * p, a = r - b;
  if (d.z < 0.f) {
    const float t = a;
    a = 1.f - b;
    b = 1.f - t;
  }
  return {clamp01(0.5f * (copysignf(a, d.x) + 1.f)), clamp01(0.5f * (copysignf(b, d.y) + 1.f))};
}

PS_INLINE Vec3 envmap_to_local(const EnvironmentMapView& e, const Vec3& w) {
  return {dot(w, e.axis_x), dot(w, e.axis_y), dot(w, e.axis_z)};
}
PS_INLINE Vec3 envmap_to_world(const EnvironmentMapView& e, const Vec3& d) {
  return e.axis_x * d.x + e.axis_y * d.y + e.axis_z * d.z;
}

PS_INLINE Rgb envmap_texel(const EnvironmentMapView& e, int x, int y) {
  return e.texels[size_t(y) * size_t(e.width) + size_t(x)];
}

// Image value at uv: bilinear between texel centres (u wraps, v clamps) for lat_long, the nearest
// texel for equal_area.
PS_INLINE Rgb envmap_lookup(const EnvironmentMapView& e, Point2 uv) {
  if (e.mapping == EnvironmentMapping::equal_area) {
    int x = int(uv.x * float(e.width)), y = int(uv.y * float(e.height));
    x = x < 0 ? 0 : (x >= e.width ? e.width - 1 : x);
    y = y < 0 ? 0 : (y >= e.height ? e.height - 1 : y);
    return envmap_texel(e, x, y);
  }
  const float x = uv.x * float(e.width) - 0.5f, y = uv.y * float(e.height) - 0.5f;
  const float fx = floorf(x), fy = floorf(y);
  const float ax = x - fx, ay = y - fy;
  int x0 = int(fx), x1 = x0 + 1, y0 = int(fy), y1 = y0 + 1;
  if (x0 < 0) x0 += e.width;
  if (x1 >= e.width) x1 -= e.width;
  y0 = y0 < 0 ? 0 : y0;
  y1 = y1 >= e.height ? e.height - 1 : y1;
  const Rgb top = envmap_texel(e, x0, y0) * (1.f - ax) + envmap_texel(e, x1, y0) * ax;
  const Rgb bottom = envmap_texel(e, x0, y1) * (1.f - ax) + envmap_texel(e, x1, y1) * ax;
  return top * (1.f - ay) + bottom * ay;
}

// Image value seen along the world direction w (towards the environment).
PS_INLINE Rgb envmap_radiance(const EnvironmentMapView& e, const Vec3& w) {
  return envmap_lookup(e, envmap_direction_to_uv(e.mapping, envmap_to_local(e, w)));
}

// Solid-angle density with which envmap_sample produces the world direction w.
PS_INLINE float envmap_pdf(const EnvironmentMapView& e, const Vec3& w) {
  const Vec3 d = envmap_to_local(e, w);
  const float pdf_uv = e.distribution.pdf(envmap_direction_to_uv(e.mapping, d));
  if (e.mapping == EnvironmentMapping::equal_area) return pdf_uv * kInvFourPi;
  const float sin_theta = sqrtf(fmaxf(0.f, 1.f - d.y * d.y));
  return sin_theta > 0.f ? pdf_uv / (2.f * kPi * kPi * sin_theta) : 0.f;
}

// Samples a world direction proportionally to the distribution; *pdf_w is envmap_pdf(*w) (so MIS
// evaluates the same function) and the return value the image value there.
PS_INLINE Rgb envmap_sample(const EnvironmentMapView& e, Point2 u, Vec3* w, float* pdf_w) {
  float pdf_uv;
  const Point2 uv = e.distribution.sample(u, &pdf_uv);
  *w = normalize(envmap_to_world(e, envmap_uv_to_direction(e.mapping, uv)));
  *pdf_w = pdf_uv > 0.f ? envmap_pdf(e, *w) : 0.f;
  return *pdf_w > 0.f ? envmap_radiance(e, *w) : Rgb();
}

}  // namespace pathspace
