// Equiangular sampling of a distance along a ray towards a point (Kulla and Fajardo 2012,
// "Importance sampling techniques for path tracing in participating media", sec. 4): the density
// of t is proportional to 1 / (h^2 + (t - delta)^2), where delta is the point's projection on the
// ray and h its distance from the ray, so the angle seen from the point is uniform. It cancels the
// 1 / distance^2 of a light's contribution: near a small light, where distance sampling rarely puts
// a scattering vertex and the few it does put make fireflies, this technique finds them.
#pragma once

#include "pathspace/base/platform.h"
#include "pathspace/math/scalar.h"
#include "pathspace/math/vec3.h"

namespace pathspace {

// The point's place relative to the ray o + t d over [t0, t1) (t1 may be infinite).
struct EquiangularFrame {
  float delta = 0.f, h = 0.f;          // projection along the ray, distance from it
  float theta0 = 0.f, theta1 = 0.f;    // angles of t0 and t1 seen from the point
  PS_HD bool valid() const { return h > 0.f && theta1 > theta0; }
};

PS_INLINE EquiangularFrame equiangular_frame(const Vec3& o, const Vec3& d, float t0, float t1, const Vec3& point) {
  EquiangularFrame f;
  const Vec3 to = point - o;
  f.delta = dot(to, d);
  f.h = length(to - d * f.delta);
  if (!(f.h > 0.f) || !isfinite(f.h)) {
    f.h = 0.f;  // the point lies on the ray's line: no angle to sample
    return f;
  }
  f.theta0 = atan2f(t0 - f.delta, f.h);
  f.theta1 = isinf(t1) ? 0.5f * kPi : atan2f(t1 - f.delta, f.h);
  return f;
}

// Density of t (0 outside the frame's interval).
PS_INLINE float equiangular_pdf(const EquiangularFrame& f, float t) {
  if (!f.valid()) return 0.f;
  const float x = t - f.delta;
  return f.h / ((f.theta1 - f.theta0) * (f.h * f.h + x * x));
}

// A distance from u in [0, 1), clamped into the interval against rounding; writes its density.
PS_INLINE float sample_equiangular(const EquiangularFrame& f, float u, float t0, float t1, float* pdf) {
  const float theta = f.theta0 + u * (f.theta1 - f.theta0);
  const float t = fminf(fmaxf(f.delta + f.h * tanf(theta), t0), t1);
  *pdf = equiangular_pdf(f, t);
  return t;
}

}  // namespace pathspace
