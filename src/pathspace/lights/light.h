// Light records (plain data, selected by LightType). What `value` means depends on the type, as in
// docs/scenes.md §5 and docs/conventions.md ("Lights and units"):
//   area_triangle / area_sphere: emitted radiance L_e (front side only unless two_sided)
//   point:       radiant intensity I (W/sr); irradiance at x is I cos / |x - p|^2
//   spot:        a point light whose intensity I is scaled by a falloff around an axis (pbrt-v4's
//                smoothstep or Mitsuba's linear fade) and optionally an image over the cone
//   projector:   a point light projecting an image through a perspective frustum (pbrt-v4's
//                projection light, Mitsuba's projector); scene/point_light_intensity.h
//   directional: irradiance E on a surface perpendicular to the beam
//   environment: constant radiance from every direction
#pragma once

#include <cstdint>

#include "pathspace/math/rgb.h"
#include "pathspace/math/vec3.h"

namespace pathspace {

// Emission below this cosine (relative to the emitting side) is zero.
inline constexpr float kMinEmitterCosine = 1e-6f;

enum class LightType : uint8_t { area_triangle, area_sphere, point, directional, environment, spot, projector };

// A spot light's fade between cos_falloff (full) and cos_total (none): pbrt-v4's smoothstep in the
// cosine, or Mitsuba's linear ramp in the angle.
enum class SpotFalloff : uint8_t { smoothstep_cosine, linear_angle };

struct Light {
  LightType type = LightType::point;
  uint32_t shape = 0;  // triangle or sphere index for area lights
  Rgb value;
  Vec3 position;       // point, spot, projector (at shutter open when it moves)
  // Motion blur (scene/motion.h): a point, spot or projector that moves while the shutter is open
  // goes in a straight line from `position` to `position_end`; its orientation stays.
  bool moves = false;
  Vec3 position_end;
  Vec3 direction;      // directional: unit direction of propagation; spot, projector: unit axis
  bool two_sided = false;
  float cos_total = -1.f;   // spot: no emission at angles whose cosine to the axis is below this
  float cos_falloff = 1.f;  // spot: full intensity above this cosine; `falloff` in between
  SpotFalloff falloff = SpotFalloff::smoothstep_cosine;
  // The image of a spot or projector (scene/point_light_intensity.h): a texture (-1: none) over
  // the plane at distance 1 along `direction`, spanned by the unit axes axis_u, axis_v (with
  // `direction` an orthonormal frame). A direction with local coordinates (x, y, z) looks up
  // uv = (0.5 + uv_scale_u x / z, 0.5 + uv_scale_v y / z); a projector emits only where uv lies in
  // [0, 1]^2. With irradiance_plane (Mitsuba's projector) the image is the irradiance on that plane,
  // so the intensity is value * image / cos^3; otherwise (pbrt-v4) value * image.
  // An area triangle's texture is its emission map (glTF emissiveTexture): radiance value * texture
  // at the surface's uv (scene/light_sampling.h area_light_radiance), positions sampled by the map's
  // brightness over emission_grid x emission_grid cells (lights/emission_cells.h; 0: by area).
  int32_t texture = -1;
  Vec3 axis_u, axis_v;
  float uv_scale_u = 0.5f, uv_scale_v = 0.5f;
  bool irradiance_plane = false;
  float image_max = 1.f;  // the texture's largest channel value (1 without one): bounds emission weights
  // Set by Scene::finalize for a mapped area triangle: its cells' offset in SceneView::emission_cells.
  uint32_t emission_cells = 0;
  uint32_t emission_grid = 0;
};

// Where a point, spot or projector is at time t in [0, 1) (its position when it stands still).
PS_INLINE Vec3 light_position(const Light& l, float time) {
  return l.moves ? l.position * (1.f - time) + l.position_end * time : l.position;
}

// Lights at a single point (delta position): point, spot and projector.
PS_INLINE bool is_point_light(const Light& l) {
  return l.type == LightType::point || l.type == LightType::spot || l.type == LightType::projector;
}
PS_INLINE bool is_delta_light(const Light& l) { return is_point_light(l) || l.type == LightType::directional; }

// The spot falloff between cos_total (0) and cos_falloff (1): pbrt-v4's smoothstep of the cosine,
// or Mitsuba's (cutoff - angle) / (cutoff - beam width).
PS_INLINE float spot_falloff(const Light& l, const Vec3& w) {
  const float c = dot(w, l.direction);
  if (c <= l.cos_total) return 0.f;
  if (c >= l.cos_falloff) return 1.f;
  if (l.falloff == SpotFalloff::linear_angle) {
    const float cutoff = acosf(l.cos_total), beam = acosf(l.cos_falloff);
    return fminf(1.f, fmaxf(0.f, (cutoff - acosf(fminf(c, 1.f))) / (cutoff - beam)));
  }
  const float t = (c - l.cos_total) / (l.cos_falloff - l.cos_total);
  return t * t * (3.f - 2.f * t);
}

// Radiant intensity of a point or spot light towards the unit direction w (leaving the light),
// before any image (scene/point_light_intensity.h multiplies spot and projector images in).
PS_INLINE Rgb point_intensity(const Light& l, const Vec3& w) {
  return l.type == LightType::spot ? l.value * spot_falloff(l, w) : l.value;
}
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
