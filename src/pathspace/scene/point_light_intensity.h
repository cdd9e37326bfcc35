// The radiant intensity of point, spot and projector lights, images included, and the projector's
// emission sampling. A spot's or projector's image lies on the plane at distance 1 along its axis
// (lights/light.h: the frame axis_u, axis_v, direction and uv = 0.5 + uv_scale * (x, y) / z):
//   spot:      I(w) = value * falloff(w) * image(uv)  (Mitsuba's spot `texture`: uv_scale 1/(2 tan cutoff))
//   projector: I(w) = value * image(uv) where uv lies in [0, 1]^2; Mitsuba's projector gives the
//              image as irradiance on the plane (irradiance_plane), I = value * image / cos^3, so a
//              constant image lights a plane at distance 1 evenly; pbrt-v4's projection light has
//              I = value * image.
// A projector's light paths start uniformly on its image plane: a direction's density is then
// 1 / (plane area * cos^3) (the plane's dA = r^3 dw at distance r = 1 / cos).
#pragma once

#include "pathspace/lights/light.h"
#include "pathspace/scene/scene_view.h"
#include "pathspace/scene/texture.h"

namespace pathspace {

// Half-widths of a projector's image plane at distance 1 (where uv spans [0, 1]).
PS_INLINE float projector_half_width_u(const Light& l) { return 0.5f / fabsf(l.uv_scale_u); }
PS_INLINE float projector_half_width_v(const Light& l) { return 0.5f / fabsf(l.uv_scale_v); }

// The image factor of a textured spot or a projector towards unit w: 0 behind the light and, for a
// projector, outside its frustum; the texture's value at the direction's uv (1 without a texture);
// divided by cos^3 for an irradiance plane. (An untextured spot has no image: point_light_intensity.)
PS_INLINE Rgb point_light_image(const SceneView& scene, const Light& l, const Vec3& w) {
  const float z = dot(w, l.direction);
  if (!(z > 0.f)) return Rgb();
  const Point2 uv{0.5f + l.uv_scale_u * dot(w, l.axis_u) / z, 0.5f + l.uv_scale_v * dot(w, l.axis_v) / z};
  if (l.type == LightType::projector && !(uv.x >= 0.f && uv.x <= 1.f && uv.y >= 0.f && uv.y <= 1.f)) return Rgb();
  Rgb image = l.texture >= 0 ? texture_lookup(scene.textures[l.texture], uv) : Rgb(1.f);
  if (l.irradiance_plane) image = image * (1.f / (z * z * z));
  return image;
}

// Radiant intensity of a point, spot or projector light towards the unit direction w.
PS_INLINE Rgb point_light_intensity(const SceneView& scene, const Light& l, const Vec3& w) {
  if (l.type == LightType::point) return l.value;
  if (l.type == LightType::spot && l.texture < 0) return point_intensity(l, w);
  const Rgb base = l.type == LightType::spot ? point_intensity(l, w) : l.value;
  return is_black(base) ? Rgb() : base * point_light_image(scene, l, w);
}

// A projector's emission direction from a uniform point of its image plane, and its density.
PS_INLINE Vec3 sample_projector_direction(const Light& l, Point2 u, float* pdf_w) {
  const float hu = projector_half_width_u(l), hv = projector_half_width_v(l);
  const Vec3 p = l.axis_u * (hu * (2.f * u.x - 1.f)) + l.axis_v * (hv * (2.f * u.y - 1.f)) + l.direction;
  const float r = length(p);
  *pdf_w = r * r * r / (4.f * hu * hv);
  return p / r;
}

// The density of sample_projector_direction for the unit direction d (0 outside the frustum).
PS_INLINE float projector_direction_pdf(const Light& l, const Vec3& d) {
  const float z = dot(d, l.direction);
  if (!(z > 0.f)) return 0.f;
  const float hu = projector_half_width_u(l), hv = projector_half_width_v(l);
  if (fabsf(dot(d, l.axis_u)) > hu * z || fabsf(dot(d, l.axis_v)) > hv * z) return 0.f;
  return 1.f / (4.f * hu * hv * z * z * z);
}

}  // namespace pathspace
