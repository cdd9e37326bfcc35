// Bounds of one light or a set of lights, for the light tree (lights/light_tree_view.h): the model
// of Conty Estevez and Kulla 2018, "Importance Sampling of Many Lights with Adaptive Tree
// Splitting", in the form pbrt-v4's BVHLightSampler uses. A set is bounded by a box holding its
// emitters, a cone of their normals (axis w, half-angle θo), the spread θe of emission around each
// normal, their total power, and whether any emits on both sides.
//
// light_bounds_importance() estimates how much the set can light a point: power over squared
// distance, times the cosines of the smallest angles the box allows. It must be conservative:
// zero only where no emitter of the set can reach the point, since the tree never picks a light
// of zero importance (a light that contributes but scores zero would be missing from the image).
#pragma once

#include "pathspace/math/bbox.h"
#include "pathspace/math/scalar.h"
#include "pathspace/math/vec3.h"

namespace pathspace {

struct LightBounds {
  Bounds3 box;
  Vec3 w{0.f, 0.f, 1.f};    // unit axis of the normals' cone
  float phi = 0.f;          // emitted power (luminance); 0: an empty set
  float cos_theta_o = 1.f;  // half-angle θo of the normals' cone (-1: every direction)
  float cos_theta_e = 0.f;  // spread θe of emission around a normal (0 = π/2: a cosine emitter)
  bool two_sided = false;
};

namespace light_bounds_detail {
// cos(max(0, a − b)) from the cosines and sines of a and b (a, b in [0, π]).
PS_INLINE float cos_of_clamped_difference(float cos_a, float sin_a, float cos_b, float sin_b) {
  if (cos_a >= cos_b) return 1.f;  // a ≤ b
  return cos_a * cos_b + sin_a * sin_b;
}
PS_INLINE float sin_of_clamped_difference(float cos_a, float sin_a, float cos_b, float sin_b) {
  if (cos_a >= cos_b) return 0.f;
  return sin_a * cos_b - cos_a * sin_b;
}
// max(0, x) as a compare and select: fmaxf's NaN rules make GCC call libm for it.
PS_INLINE float positive_part(float x) { return x > 0.f ? x : 0.f; }
PS_INLINE float sin_from_cos(float c) { return sqrtf(positive_part(1.f - c * c)); }
}  // namespace light_bounds_detail

// What the importance needs of a set's bounds, precomputed per tree node: the box's bounding sphere
// and the sine of θo.
struct LightImportanceBounds {
  Vec3 center;
  float radius2 = 0.f;  // squared radius of the box's bounding sphere
  Vec3 w{0.f, 0.f, 1.f};
  float phi = 0.f;
  float cos_theta_o = 1.f, sin_theta_o = 0.f, cos_theta_e = 0.f;
  bool two_sided = false;
};

PS_INLINE LightImportanceBounds importance_bounds(const LightBounds& b) {
  LightImportanceBounds r;
  r.center = b.box.center();
  const Vec3 half = b.box.diagonal() * 0.5f;
  r.radius2 = b.phi > 0.f ? length_squared(half) : 0.f;
  r.w = b.w;
  r.phi = b.phi;
  r.cos_theta_o = b.cos_theta_o;
  r.sin_theta_o = light_bounds_detail::sin_from_cos(b.cos_theta_o);
  r.cos_theta_e = b.cos_theta_e;
  r.two_sided = b.two_sided;
  return r;
}

// Importance of the set `b` at point p with unit surface normal n (zero vector: a point in a medium
// or with no surface, where the receiver's cosine is not known).
PS_INLINE float light_bounds_importance(const LightImportanceBounds& b, const Vec3& p, const Vec3& n) {
  using namespace light_bounds_detail;
  if (!(b.phi > 0.f)) return 0.f;
  const Vec3 to_p = p - b.center;
  const float d2 = length_squared(to_p);
  // Inside the bounding sphere every direction is possible: the power over the sphere's size.
  if (!(d2 > b.radius2)) return b.radius2 > 0.f ? b.phi / b.radius2 : b.phi;
  const Vec3 wi = to_p * (1.f / sqrtf(d2));  // from the lights towards p

  // θb: half-angle of the cone from p that holds the bounding sphere.
  const float sin2_b = b.radius2 / d2;
  const float cos_b = sqrtf(positive_part(1.f - sin2_b)), sin_b = sqrtf(sin2_b);

  // The smallest angle between an emitter normal and the direction to p: θ' = max(0, θw − θo − θb).
  float cos_w = dot(b.w, wi);
  if (b.two_sided) cos_w = fabsf(cos_w);
  const float sin_w = sin_from_cos(cos_w);
  const float cos_wo = cos_of_clamped_difference(cos_w, sin_w, b.cos_theta_o, b.sin_theta_o);
  const float sin_wo = sin_of_clamped_difference(cos_w, sin_w, b.cos_theta_o, b.sin_theta_o);
  const float cos_p = cos_of_clamped_difference(cos_wo, sin_wo, cos_b, sin_b);
  if (cos_p <= b.cos_theta_e) return 0.f;  // no emitter of the set faces p

  float importance = b.phi * cos_p / d2;
  if (n.x != 0.f || n.y != 0.f || n.z != 0.f) {
    // The receiver's cosine at its largest over the sphere: θi' = max(0, θi − θb), either side.
    const float cos_i = fabsf(dot(wi, n));
    importance *= cos_of_clamped_difference(cos_i, sin_from_cos(cos_i), cos_b, sin_b);
  }
  return positive_part(importance);
}

}  // namespace pathspace
