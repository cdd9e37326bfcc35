// Next-event estimation for every light type: sample a direction towards the light, its solid-angle
// pdf (for MIS when a BSDF-sampled ray hits an emitter), and emitted radiance.
// Triangles: uniform area sampling, or by an emission map's brightness (lights/emission_cells.h).
// Spheres: uniform cone of directions from outside, uniform area from inside (the only choice for
// the "inside of a sphere" test scenes).
#pragma once

#include "pathspace/geometry/interaction.h"
#include "pathspace/geometry/surface_attributes.h"
#include "pathspace/scene/environment_light.h"
#include "pathspace/scene/point_light_intensity.h"
#include "pathspace/lights/emission_cells.h"
#include "pathspace/lights/light.h"
#include "pathspace/math/frame.h"
#include "pathspace/sampling/warps.h"
#include "pathspace/scene/motion.h"
#include "pathspace/scene/scene_view.h"

namespace pathspace {

// Emitted radiance leaving an area light at a point with geometric normal n towards w.
PS_INLINE Rgb area_light_radiance(const Light& l, const Vec3& n, const Vec3& w) {
  const float c = dot(n, w);
  if (c > kMinEmitterCosine || (l.two_sided && c < -kMinEmitterCosine)) return l.value;
  return {};
}

// The same at a point with texture coordinates uv: times the light's emission map there, if it has
// one (an area triangle's texture, glTF emissiveTexture). Every place that sees an area light's
// radiance (a hit, a light sample, a light path's first vertex) goes through here.
PS_INLINE Rgb area_light_radiance(const SceneView& scene, const Light& l, const Vec3& n, const Vec3& w, Point2 uv) {
  const Rgb le = area_light_radiance(l, n, w);
  if (l.texture < 0 || is_black(le)) return le;
  return le * texture_lookup(scene.textures[l.texture], uv);
}

// Where an area triangle's emission map is read for a point sampled at barycentrics b (as
// square_to_triangle_barycentric gives them: b.x for vertex 0, b.y for vertex 1). Lights without a
// map skip the interpolation (every next-event estimate passes here).
PS_INLINE Point2 emission_map_uv(const SceneView& scene, const Light& l, Point2 b) {
  return l.texture >= 0 ? triangle_uv(scene.triangles[l.shape], scene.uvs, b.y, 1.f - b.x - b.y) : Point2{};
}

// Where a sample lands on an area triangle: by its emission map's cells when it has them, else
// uniformly by area. Returns barycentrics as square_to_triangle_barycentric does and writes the area
// density times the triangle's area.
PS_INLINE Point2 sample_triangle_emitter(const SceneView& scene, const Light& l, Point2 u, float* density_times_area) {
  if (l.emission_grid == 0) {
    *density_times_area = 1.f;
    return square_to_triangle_barycentric(u);
  }
  return sample_emission_cells(scene.emission_cells + l.emission_cells, l.emission_grid, u, density_times_area);
}

// The point of triangle tv at barycentrics b as sample_triangle_emitter gives them (b.x of p0, b.y of
// p1): light samples, light paths and equiangular anchors all place it by this one expression.
PS_INLINE Vec3 triangle_emitter_point(const TriangleVertices& tv, Point2 b) {
  return tv.p0 * b.x + tv.p1 * b.y + tv.p2 * (1.f - b.x - b.y);
}

// The area density with which sample_triangle_emitter lands at p on the light's triangle tv.
PS_INLINE float triangle_emitter_pdf_a(const SceneView& scene, const Light& l, const TriangleVertices& tv, const Vec3& p) {
  const float area = triangle_area(tv.p0, tv.p1, tv.p2);
  if (!(area > 0.f)) return 0.f;
  if (l.emission_grid == 0) return 1.f / area;
  const Point2 b = triangle_barycentrics_of(p, tv.p0, tv.p1, tv.p2);
  return emission_cells_density(scene.emission_cells + l.emission_cells, l.emission_grid, b) / area;
}

// The point equiangular sampling (integrators/pt/pt_kernel.h) aims a segment's distance at, for
// light l and the numbers u of its light sample: where sample_light puts the point when that does not
// depend on the reference point (area triangles; point, spot, projector), so the same u gives the
// same point from anywhere; a sphere's centre, whose samples do depend on it. False for distant and
// environment lights (no point to aim at).
PS_INLINE bool equiangular_anchor(const SceneView& scene, const Light& l, float time, Point2 u, Vec3* p) {
  if (is_point_light(l)) {
    *p = light_position(l, time);
    return true;
  }
  if (l.type == LightType::area_sphere) {
    *p = scene.spheres[l.shape].center;
    return true;
  }
  if (l.type != LightType::area_triangle) return false;
  const TriangleVertices tv = triangle_at(scene, scene.triangles[l.shape], time);
  float density_times_area;
  const Point2 b = sample_triangle_emitter(scene, l, u, &density_times_area);
  *p = triangle_emitter_point(tv, b);
  return true;
}

// The same anchor known from the light sample sample_light made (its point `sampled`).
PS_INLINE bool equiangular_anchor_of_sample(const SceneView& scene, const Light& l, const Vec3& sampled, Vec3* p) {
  if (l.type == LightType::area_sphere) {
    *p = scene.spheres[l.shape].center;
    return true;
  }
  *p = sampled;
  return is_point_light(l) || l.type == LightType::area_triangle;
}

namespace detail {
PS_INLINE float solid_angle_from_area(float pdf_a, const Vec3& ref, const Vec3& p, const Vec3& n) {
  const Vec3 d = p - ref;
  const float d2 = length_squared(d);
  const float c = fabsf(dot(n, d)) / sqrtf(d2);
  return c > 0.f ? pdf_a * d2 / c : 0.f;
}
}  // namespace detail

// A direction from `ref` towards light l at `time` (a moving emitter where it is then).
PS_INLINE bool sample_light(const SceneView& scene, const Light& l, const Vec3& ref, float time, Point2 u, LightSample* s) {
  switch (l.type) {
    case LightType::area_triangle: {
      const TriangleVertices tv = triangle_at(scene, scene.triangles[l.shape], time);
      const Vec3 &p0 = tv.p0, &p1 = tv.p1, &p2 = tv.p2;
      float density_times_area;
      const Point2 b = sample_triangle_emitter(scene, l, u, &density_times_area);
      const Vec3 p = triangle_emitter_point(tv, b);
      const Vec3 n = triangle_normal(p0, p1, p2);
      const Vec3 d = p - ref;
      const float dist = length(d);
      if (dist <= 0.f) return false;
      s->wi = d / dist;
      s->dist = dist;
      s->p = p;
      s->li = area_light_radiance(scene, l, n, -s->wi, emission_map_uv(scene, l, b));
      s->pdf_w = detail::solid_angle_from_area(density_times_area / triangle_area(p0, p1, p2), ref, p, n);
      s->delta = false;
      return s->pdf_w > 0.f && !is_black(s->li);
    }
    case LightType::area_sphere: {
      const Sphere& sp = scene.spheres[l.shape];
      const Vec3 to_c = sp.center - ref;
      const float dc2 = length_squared(to_c);
      const float r2 = sp.radius * sp.radius;
      Vec3 p;
      if (dc2 > r2 * 1.0001f) {  // outside: sample the cone of directions subtended by the sphere
        const float dc = sqrtf(dc2);
        const float sin2_max = r2 / dc2;
        const float cos_max = sqrtf(fmaxf(0.f, 1.f - sin2_max));
        const Frame f(to_c / dc);
        const Vec3 wi = f.to_world(square_to_uniform_cone(u, cos_max));
        float t;
        if (!intersect_sphere(sp, ref, wi, 0.f, kInfinity, &t)) {
          // Grazing sample missed by rounding: take the tangent point.
          t = dot(to_c, wi);
        }
        p = ref + wi * t;
        s->pdf_w = uniform_cone_pdf(cos_max);
        s->wi = wi;
        s->dist = t;
      } else {  // inside (or on): uniform area
        p = sp.center + square_to_uniform_sphere(u) * sp.radius;
        const Vec3 d = p - ref;
        s->dist = length(d);
        if (s->dist <= 0.f) return false;
        s->wi = d / s->dist;
        s->pdf_w = detail::solid_angle_from_area(1.f / (kFourPi * r2), ref, p, sphere_normal(sp, p));
      }
      s->p = p;
      s->li = area_light_radiance(l, sphere_normal(sp, p), -s->wi);
      s->delta = false;
      return s->pdf_w > 0.f && isfinite(s->pdf_w) && !is_black(s->li);
    }
    case LightType::point:
    case LightType::spot:
    case LightType::projector: {
      const Vec3 at = light_position(l, time);
      const Vec3 d = at - ref;
      const float d2 = length_squared(d);
      if (!(d2 > 0.f)) return false;
      s->dist = sqrtf(d2);
      s->wi = d / s->dist;
      s->p = at;
      s->li = point_light_intensity(scene, l, -s->wi) / d2;
      s->pdf_w = 1.f;
      s->delta = true;
      return !is_black(s->li);
    }
    case LightType::directional:
      s->wi = -l.direction;
      s->dist = kInfinity;
      s->li = l.value;
      s->pdf_w = 1.f;
      s->delta = true;
      return true;
    case LightType::environment:
      s->li = sample_environment(scene, l, u, &s->wi, &s->pdf_w);
      s->dist = kInfinity;
      s->delta = false;
      return s->pdf_w > 0.f && !is_black(s->li);
  }
  return false;
}

// Solid-angle pdf with which sample_light would produce the direction from `ref` to the point `p`
// (normal n) on light l; for the environment light only the direction p - ref matters (pass
// ref + w). `time`: the path's, at which a moving emitter's area is taken.
PS_INLINE float light_pdf(const SceneView& scene, const Light& l, const Vec3& ref, const Vec3& p, const Vec3& n, float time) {
  switch (l.type) {
    case LightType::area_triangle: {
      const TriangleVertices tv = triangle_at(scene, scene.triangles[l.shape], time);
      return detail::solid_angle_from_area(triangle_emitter_pdf_a(scene, l, tv, p), ref, p, n);
    }
    case LightType::area_sphere: {
      const Sphere& sp = scene.spheres[l.shape];
      const float dc2 = distance_squared(sp.center, ref);
      const float r2 = sp.radius * sp.radius;
      if (dc2 > r2 * 1.0001f) {
        const float cos_max = sqrtf(fmaxf(0.f, 1.f - r2 / dc2));
        return uniform_cone_pdf(cos_max);
      }
      return detail::solid_angle_from_area(1.f / (kFourPi * r2), ref, p, n);
    }
    case LightType::environment: return environment_pdf(scene, normalize(p - ref));
    default: return 0.f;  // delta lights cannot be hit
  }
}

}  // namespace pathspace
