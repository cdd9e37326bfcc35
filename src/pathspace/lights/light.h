// Light records (plain data, selected by LightType). What `value` means depends on the type,
// exactly as in cornell-variants.md §5:
//   area_triangle / area_sphere: emitted radiance L_e (front side only unless two_sided)
//   point:       radiant intensity I (W/sr); irradiance at x is I cos / |x - p|^2
//   directional: irradiance E on a surface perpendicular to the beam
//   environment: constant radiance from every direction
#pragma once

#include <cstdint>

#include "pathspace/math/rgb.h"
#include "pathspace/math/vec3.h"

namespace pathspace {

// Emission below this cosine (relative to the emitting side) is zero.
inline constexpr float kMinEmitterCosine = 1e-6f;

enum class LightType : uint8_t { area_triangle, area_sphere, point, directional, environment };

struct Light {
  LightType type = LightType::point;
  uint32_t shape = 0;  // triangle or sphere index for area lights
  Rgb value;
  Vec3 position;       // point
  Vec3 direction;      // directional: unit direction of propagation
  bool two_sided = false;
};

PS_INLINE bool is_delta_light(const Light& l) { return l.type == LightType::point || l.type == LightType::directional; }
PS_INLINE bool is_area_light(const Light& l) { return l.type == LightType::area_triangle || l.type == LightType::area_sphere; }

// Sample towards a light from a reference point (next event estimation).
struct LightSample {
  Vec3 wi;                 // unit, from the reference point towards the light
  float dist = kInfinity;  // to the sampled point (infinite for directional and environment)
  Vec3 p;                  // sampled point on the light (area and point lights)
  Rgb li;                  // incident radiance (area, environment), I / d^2 (point) or E (directional)
  float pdf_w = 0.f;       // solid-angle density of wi (1 for delta lights)
  bool delta = false;
};

}  // namespace pathspace
