// Emission sampling: the first vertex and direction of a light path (light tracing, and BPT/PCLT
// later), for every light type (Veach 1997 §10.2 "sampling the light sources"; SmallVCM's
// Emit() conventions, docs/scenes.md §5). Area lights: uniform area (triangles with an emission map: by its
// brightness, lights/emission_cells.h), then cosine-weighted
// around the emitting side; point: uniform sphere; directional and environment: parallel rays
// from a disk of the scene's bounding sphere perpendicular to the propagation direction.
#pragma once

#include "pathspace/scene/light_sampling.h"

namespace pathspace {

struct EmissionSample {
  Vec3 p;                 // origin on the light (on the bounding-sphere disk for infinite lights)
  Vec3 n;                 // emitting-side normal (area lights); the propagation direction otherwise
  Vec3 ng;                // the light's geometric normal at p (area lights), for two-sided emitters
  Vec3 d;                 // unit propagation direction
  Rgb le;                 // emitted radiance at (p, d) for area/environment lights; I or E for delta lights
  Point2 uv;              // area triangles with an emission map: the surface's texture coordinates at p
  Rgb weight;             // le |cos| / (pdf_a pdf_w): the light-path throughput after emission
  float pdf_a = 0.f;      // area density of p (1 for a point light)
  float pdf_w = 0.f;      // solid-angle density of d (1 for a directional light)
  bool delta_position = false;   // point light: nothing can hit it
  bool delta_direction = false;  // directional light
  bool infinite = false;         // directional / environment: p is a proxy on a disk
  float time = 0.f;              // the light path's time (scene/motion.h); its rays carry it
};

namespace emission_detail {
// Cosine-weighted direction around n (the emitting side). With `two_sided` the side is chosen by the
// sign of u.x remapped, each with probability 1/2, so pdf_w halves.
PS_INLINE Vec3 cosine_around(const Vec3& n, Point2 u, bool two_sided, Vec3* side, float* pdf_w) {
  Vec3 s = n;
  float side_prob = 1.f;
  if (two_sided) {
    side_prob = 0.5f;
    if (u.x < 0.5f) {
      u.x *= 2.f;
    } else {
      u.x = (u.x - 0.5f) * 2.f;
      s = -n;
    }
    if (u.x >= 1.f) u.x = 0.99999994f;
  }
  const Vec3 local = square_to_cosine_hemisphere(u);
  *side = s;
  *pdf_w = side_prob * cosine_hemisphere_pdf(local);
  return Frame(s).to_world(local);
}

// Uniform point on the disk of radius r centred at c, perpendicular to d.
PS_INLINE Vec3 disk_point(const Vec3& c, const Vec3& d, float r, Point2 u) {
  const Point2 q = square_to_disk_concentric(u);
  const Frame f(d);
  return c + (f.s * q.x + f.t * q.y) * r;
}
}  // namespace emission_detail

// Samples an emission from light l at `time` (a moving emitter where it is then) with four uniform
// numbers. Returns false for a zero sample.
PS_INLINE bool sample_emission(const SceneView& scene, const Light& l, float time, Point2 u_pos, Point2 u_dir,
                               EmissionSample* e) {
  using namespace emission_detail;
  e->delta_position = e->delta_direction = e->infinite = false;
  e->time = time;
  switch (l.type) {
    case LightType::area_triangle:
    case LightType::area_sphere: {
      Vec3 p, n;
      float area, density_times_area = 1.f;
      if (l.type == LightType::area_triangle) {
        const TriangleVertices tv = triangle_at(scene, scene.triangles[l.shape], time);
        const Vec3 &p0 = tv.p0, &p1 = tv.p1, &p2 = tv.p2;
        const Point2 b = sample_triangle_emitter(scene, l, u_pos, &density_times_area);
        p = triangle_emitter_point(tv, b);
        n = triangle_normal(p0, p1, p2);
        area = triangle_area(p0, p1, p2);
        e->uv = emission_map_uv(scene, l, b);
      } else {
        const Sphere& sp = scene.spheres[l.shape];
        p = sp.center + square_to_uniform_sphere(u_pos) * sp.radius;
        n = sphere_normal(sp, p);
        area = kFourPi * sp.radius * sp.radius;
      }
      Vec3 side;
      float pdf_w;
      e->d = cosine_around(n, u_dir, l.two_sided, &side, &pdf_w);
      const float c = dot(side, e->d);
      if (!(area > 0.f) || c <= kMinEmitterCosine || pdf_w <= 0.f) return false;
      e->p = p;
      e->n = side;
      e->ng = n;
      e->le = area_light_radiance(scene, l, side, side, e->uv);  // along the emitting side: the light's value (and map)
      e->pdf_a = density_times_area / area;
      e->pdf_w = pdf_w;
      e->weight = e->le * (c / (e->pdf_a * pdf_w));
      return !is_black(e->le);
    }
    case LightType::point:
      e->p = light_position(l, time);
      e->d = square_to_uniform_sphere(u_dir);
      e->n = e->ng = e->d;
      e->le = l.value;
      e->pdf_a = 1.f;
      e->pdf_w = uniform_sphere_pdf();
      e->weight = l.value * (1.f / e->pdf_w);  // I / pdf_w: flux carried by one direction sample
      e->delta_position = true;
      return !is_black(l.value);
    case LightType::spot: {  // directions uniform in the cone; the falloff goes into the weight
      const Frame f(l.direction);
      e->p = light_position(l, time);
      e->d = f.to_world(square_to_uniform_cone(u_dir, l.cos_total));
      e->n = e->ng = e->d;
      e->le = point_light_intensity(scene, l, e->d);
      e->pdf_a = 1.f;
      e->pdf_w = uniform_cone_pdf(l.cos_total);
      e->weight = e->le * (1.f / e->pdf_w);
      e->delta_position = true;
      return !is_black(e->le);
    }
    case LightType::projector: {  // directions from uniform points of the image plane
      e->p = light_position(l, time);
      e->d = sample_projector_direction(l, u_dir, &e->pdf_w);
      e->n = e->ng = e->d;
      e->le = point_light_intensity(scene, l, e->d);
      e->pdf_a = 1.f;
      e->weight = e->le * (1.f / e->pdf_w);
      e->delta_position = true;
      return !is_black(e->le) && e->pdf_w > 0.f;
    }
    case LightType::directional:
    case LightType::environment: {
      const BoundingSphere& b = scene.bounds;
      if (l.type == LightType::directional) {
        e->d = l.direction;
        e->pdf_w = 1.f;
        e->delta_direction = true;
        e->le = l.value;
      } else if (!scene.environment_map.texels) {
        e->d = square_to_uniform_sphere(u_dir);
        e->pdf_w = uniform_sphere_pdf();
        e->le = l.value;
      } else {
        // Propagation is opposite to the direction towards the environment.
        Vec3 w;
        e->le = sample_environment(scene, l, u_dir, &w, &e->pdf_w);
        e->d = -w;
        if (!(e->pdf_w > 0.f)) return false;
      }
      // The disk lies on the far side of the bounding sphere (upstream), so every ray crosses the
      // whole scene; flux through it is value * pi R^2 per direction.
      e->p = disk_point(b.center - e->d * b.radius, e->d, b.radius, u_pos);
      e->n = e->ng = e->d;
      e->pdf_a = 1.f / (kPi * b.radius * b.radius);
      e->weight = e->le * (1.f / (e->pdf_a * e->pdf_w));
      e->infinite = true;
      return !is_black(e->le) && b.radius > 0.f;
    }
  }
  return false;
}

// Densities with which sample_emission produces the emission (p, d) from light l (for MIS in BPT):
// pdf_a of the origin and pdf_w of the direction. For area lights p is the origin and n the light's
// geometric normal there, at `time`; other lights ignore p.
PS_INLINE void emission_pdf(const SceneView& scene, const Light& l, const Vec3& p, const Vec3& n, const Vec3& d, float time,
                            float* pdf_a, float* pdf_w) {
  *pdf_a = 0.f;
  *pdf_w = 0.f;
  switch (l.type) {
    case LightType::area_triangle:
    case LightType::area_sphere: {
      if (l.type == LightType::area_triangle) {
        *pdf_a = triangle_emitter_pdf_a(scene, l, triangle_at(scene, scene.triangles[l.shape], time), p);
      } else {
        const float r = scene.spheres[l.shape].radius;
        *pdf_a = 1.f / (kFourPi * r * r);
      }
      const float c = dot(n, d);
      const bool emits = c > kMinEmitterCosine || (l.two_sided && c < -kMinEmitterCosine);
      *pdf_w = emits ? fabsf(c) * kInvPi * (l.two_sided ? 0.5f : 1.f) : 0.f;
      return;
    }
    case LightType::point:
      *pdf_a = 1.f;
      *pdf_w = uniform_sphere_pdf();
      return;
    case LightType::spot:
      *pdf_a = 1.f;
      *pdf_w = dot(d, l.direction) > l.cos_total ? uniform_cone_pdf(l.cos_total) : 0.f;
      return;
    case LightType::projector:
      *pdf_a = 1.f;
      *pdf_w = projector_direction_pdf(l, d);
      return;
    case LightType::directional:
    case LightType::environment:
      *pdf_a = scene.bounds.radius > 0.f ? 1.f / (kPi * scene.bounds.radius * scene.bounds.radius) : 0.f;
      *pdf_w = l.type == LightType::directional ? 1.f : environment_pdf(scene, -d);
      return;
  }
}

}  // namespace pathspace
