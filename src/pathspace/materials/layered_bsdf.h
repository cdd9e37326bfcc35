// Layered BSDFs: a dielectric coat over a Lambertian or conductor base with a homogeneous slab
// between them, pbrt-v4's coateddiffuse and coatedconductor (pbrt-v4 book sec. 14.3; the
// position-free random walk of Guo, Hasan and Zhao 2018, "Position-Free Monte Carlo Simulation for
// Arbitrary Layered BSDFs"). Two-sided, reflection only (neither base transmits).
//
// eval: the coat's own reflection (a rough coat's microfacet lobe; a smooth coat's mirror is a delta
//   lobe) plus an unbiased estimate of the light that enters the slab: n_samples random walks between
//   the interfaces, each event connected to wi by next event estimation through the coat (MIS
//   between the two connections where the coat is rough). The walk's random numbers hash (wo, wi), so
//   eval is a deterministic function whose error differs from one direction pair to the next.
// pdf / sample: an exact mixture density, so that MIS, the bidirectional integrators and the
//   chi-square tests see the density the samples have (pbrt-v4 returns a walk's pdf instead, which
//   only approximates it): the coat's reflection lobe (visible normals, rough coats), a lobe for the
//   base (cosine for Lambert; for a conductor a GGX lobe about the mirror direction as wide as the
//   base seen through the coat) and a cosine floor. weight = eval |cos| / pdf.
// A smooth coat over a smooth conductor reflects only in the mirror direction: closed form
// (the geometric series of internal reflections), a delta lobe.
#pragma once

#include "pathspace/materials/bsdf_sample.h"
#include "pathspace/materials/fresnel.h"
#include "pathspace/materials/material.h"
#include "pathspace/materials/microfacet_distribution.h"
#include "pathspace/materials/rough_conductor.h"
#include "pathspace/materials/rough_dielectric.h"
#include "pathspace/media/henyey_greenstein.h"
#include "pathspace/math/frame.h"
#include "pathspace/sampling/hash.h"
#include "pathspace/sampling/rng.h"
#include "pathspace/sampling/warps.h"

namespace pathspace::layered {

// Below this roughness an interface is a perfect mirror / refractor (pbrt's EffectivelySmooth).
inline constexpr float kSmoothAlpha = 1e-3f;

// One scattering event of the walk: weight = f |cos wi| / pdf (pdf 1 for a delta event).
struct Event {
  Vec3 wi;
  Rgb weight;
  float pdf = 0.f;
  bool delta = false;
};

// ---- The coat: a dielectric interface between the outside (z > 0) and the slab (ior = n_slab / n_outside).

// The sub-materials are copies of m with their own type and fields (a copy is also what the device can do).
PS_INLINE Material coat_material(const Material& m) {
  Material c = m;
  c.type = MaterialType::rough_dielectric;
  c.two_sided = false;
  c.specular = Rgb(1.f);
  return c;
}
PS_INLINE bool coat_smooth(const Material& m) { return m.alpha < kSmoothAlpha; }

// The density coat_sample_* gives wi (0 for a smooth coat, whose events are deltas).
PS_INLINE float coat_pdf(const Material& m, const Material& coat, const Vec3& wo, const Vec3& wi) {
  if (coat_smooth(m)) return 0.f;
  const rough_dielectric::HalfVector hv = rough_dielectric::half_vector(coat, wo, wi);
  if (!hv.valid) return 0.f;
  const float pdf_h = microfacet::visible_normal_pdf(wo, hv.h, microfacet::clamp_alpha(m.alpha), m.distribution);
  if (hv.reflect) return pdf_h / (4.f * fabsf(dot(wo, hv.h)));
  return pdf_h * fabsf(dot(wi, hv.h)) / rough_dielectric::transmission_denominator(wo, wi, hv);
}

// Transmission through the coat from wo's side, sampled alone (the walk's entry and exit).
PS_INLINE bool coat_sample_transmission(const Material& m, const Material& coat, const Vec3& wo, Point2 u,
                                        TransportMode mode, Event* e) {
  if (fabsf(wo.z) < kMinCosine) return false;
  if (coat_smooth(m)) {
    const float f = fresnel_dielectric(wo.z, m.ior);
    if (f >= 1.f || !refract_local(wo, m.ior, &e->wi)) return false;
    const float etap = wo.z > 0.f ? m.ior : 1.f / m.ior;  // n_wi / n_wo
    e->weight = Rgb(mode == TransportMode::radiance ? (1.f - f) / sqr(etap) : 1.f - f);
    e->pdf = 1.f;
    e->delta = true;
    return true;
  }
  const Vec3 h = microfacet::sample_visible_normal(wo, microfacet::clamp_alpha(m.alpha), m.distribution, u);
  Vec3 wi;
  float etap;
  if (!rough_dielectric::refract_about(wo, h, m.ior, &wi, &etap)) return false;
  e->pdf = coat_pdf(m, coat, wo, wi);
  if (!(e->pdf > 0.f)) return false;
  e->wi = wi;
  e->weight = rough_dielectric::eval(coat, wo, wi, mode) * (fabsf(wi.z) / e->pdf);
  e->delta = false;
  return true;
}

// Reflection at the coat, sampled alone (inside the slab: from below).
PS_INLINE bool coat_sample_reflection(const Material& m, const Material& coat, const Vec3& wo, Point2 u,
                                      TransportMode mode, Event* e) {
  if (fabsf(wo.z) < kMinCosine) return false;
  if (coat_smooth(m)) {
    e->wi = Vec3(-wo.x, -wo.y, wo.z);
    e->weight = Rgb(fresnel_dielectric(wo.z, m.ior));
    e->pdf = 1.f;
    e->delta = true;
    return true;
  }
  const float alpha = microfacet::clamp_alpha(m.alpha);
  const Vec3 h = microfacet::sample_visible_normal(wo, alpha, m.distribution, u);
  const Vec3 wi = reflect(wo, h);
  if (wi.z * wo.z <= 0.f) return false;
  const float wo_h = fabsf(dot(wo, h));
  e->pdf = microfacet::visible_normal_pdf(wo, h, alpha, m.distribution) / (4.f * wo_h);
  if (!(e->pdf > 0.f)) return false;
  e->wi = wi;
  e->weight = rough_dielectric::eval(coat, wo, wi, mode) * (fabsf(wi.z) / e->pdf);
  e->delta = false;
  return true;
}

PS_INLINE Rgb coat_eval(const Material& m, const Material& coat, const Vec3& wo, const Vec3& wi, TransportMode mode) {
  return coat_smooth(m) ? Rgb() : rough_dielectric::eval(coat, wo, wi, mode);
}

// ---- The base, seen from the slab (wo.z > 0): Lambert, or a conductor with eta and k relative to the slab.

PS_INLINE bool base_delta(const Material& m) {
  return m.type == MaterialType::coated_conductor && m.base_alpha < kSmoothAlpha;
}
PS_INLINE Material base_conductor(const Material& m) {
  Material c = m;
  c.type = MaterialType::rough_conductor;
  c.two_sided = false;
  c.alpha = m.base_alpha;
  return c;
}

PS_INLINE Rgb base_eval(const Material& m, const Vec3& wo, const Vec3& wi) {
  if (m.type == MaterialType::coated_diffuse)
    return wo.z >= kMinCosine && wi.z >= kMinCosine ? m.diffuse * kInvPi : Rgb();
  if (base_delta(m)) return {};
  return rough_conductor::eval(base_conductor(m), wo, wi, TransportMode::radiance);
}

PS_INLINE float base_pdf(const Material& m, const Vec3& wo, const Vec3& wi) {
  if (m.type == MaterialType::coated_diffuse) return wo.z >= kMinCosine ? cosine_hemisphere_pdf(wi) : 0.f;
  if (base_delta(m)) return 0.f;
  return rough_conductor::pdf(base_conductor(m), wo, wi, TransportMode::radiance);
}

PS_INLINE bool base_sample(const Material& m, const Vec3& wo, Point2 u, Event* e) {
  if (wo.z < kMinCosine) return false;
  if (m.type == MaterialType::coated_diffuse) {
    e->wi = square_to_cosine_hemisphere(u);
    e->pdf = cosine_hemisphere_pdf(e->wi);
    e->weight = m.diffuse;
    e->delta = false;
    return e->pdf > 0.f;
  }
  if (base_delta(m)) {
    e->wi = Vec3(-wo.x, -wo.y, wo.z);
    e->weight = fresnel_conductor(wo.z, m.eta, m.k);
    e->pdf = 1.f;
    e->delta = true;
    return true;
  }
  BsdfSample s;
  if (!rough_conductor::sample(base_conductor(m), wo, 0.f, u, TransportMode::radiance, &s)) return false;
  e->wi = s.wi;
  e->weight = s.weight;
  e->pdf = s.pdf_w;
  e->delta = false;
  return true;
}

// ---- The slab: transmittance over a height dz along w (thickness in mean free paths); its phase
// function is media/henyey_greenstein.h.

PS_INLINE float transmittance(float dz, const Vec3& w) { return expf(-fabsf(dz / w.z)); }

PS_INLINE float power_heuristic(float a, float b) {
  const float a2 = a * a, b2 = b * b;
  return a2 + b2 > 0.f ? a2 / (a2 + b2) : 0.f;
}

// The walk's random numbers: a stream seeded by the bits of both directions.
PS_INLINE Pcg32 walk_rng(const Vec3& a, const Vec3& b) {
  const uint64_t ha = hash_combine(hash_combine(float_bits(a.x), float_bits(a.y)), float_bits(a.z));
  const uint64_t hb = hash_combine(hash_combine(float_bits(b.x), float_bits(b.y)), float_bits(b.z));
  return Pcg32(ha, hb);
}

// ---- Smooth coat over a smooth conductor: a mirror whose reflectance sums the internal bounces.

PS_INLINE Rgb mirror_reflectance(const Material& m, float cos_o) {
  float cos_t;
  const float f = fresnel_dielectric(cos_o, m.ior, &cos_t);
  if (f >= 1.f || cos_t < kMinCosine) return Rgb(f);
  const Rgb rb = fresnel_conductor(cos_t, m.eta, m.k) * sqr(expf(-m.thickness / cos_t));
  Rgb r;
  for (int c = 0; c < 3; ++c) r[c] = f + sqr(1.f - f) * rb[c] / (1.f - f * rb[c]);
  return r;
}
PS_INLINE bool pure_mirror(const Material& m) { return coat_smooth(m) && base_delta(m); }

// ---- eval: f of the non-delta part, wo and wi above the surface (bsdf.h mirrors two-sided materials).
// eval, pdf and sample are out of line on the GPU (PS_INLINE_HOST_ONLY): inlined, their random walks
// cost every path tracing thread registers and spills, coated or not (1.66x the frame time on the
// Cornell box, docs/gpu.md).

PS_INLINE_HOST_ONLY Rgb eval(const Material& m, const Vec3& wo, const Vec3& wi, TransportMode mode) {
  if (wo.z < kMinCosine || wi.z < kMinCosine || pure_mirror(m)) return {};
  const Material coat = coat_material(m);
  Rgb f = coat_eval(m, coat, wo, wi, mode);
  const TransportMode adjoint = mode == TransportMode::radiance ? TransportMode::importance : TransportMode::radiance;
  const bool exit_delta = coat_smooth(m), bottom_delta = base_delta(m);
  const bool scatters = !is_black(m.medium_albedo);
  const float thickness = m.thickness;
  Pcg32 rng = walk_rng(wo, wi);
  const auto r = [&rng] { return rng.next_float(); };
  // Each connection to wi has two strategies where both interfaces are rough: the adjoint walk's first
  // direction `light` (density coat_pdf(wi, light.wi)) and the walk's own next direction (the base's
  // or the phase function's density); both weights use the same two densities, so they sum to 1.
  Rgb sum;
  const int n = m.n_samples > 0 ? m.n_samples : 1;
  for (int s = 0; s < n; ++s) {
    Event enter, light;  // into the slab from wo, and from wi (the adjoint walk's first step)
    if (!coat_sample_transmission(m, coat, wo, {r(), r()}, mode, &enter)) continue;
    if (!coat_sample_transmission(m, coat, wi, {r(), r()}, adjoint, &light)) continue;
    const float light_cos = fabsf(light.wi.z);
    Rgb beta = enter.weight;
    Vec3 w = enter.wi;  // travel direction, downwards
    float z = thickness;
    for (int depth = 0; depth < m.max_depth; ++depth) {
      if (depth > 3 && max_component(beta) < 0.25f) {  // Russian roulette
        const float q = fmaxf(0.f, 1.f - max_component(beta));
        if (r() < q) break;
        beta *= 1.f / (1.f - q);
      }
      if (!scatters) {
        beta *= transmittance(thickness, w);
        z = z == thickness ? 0.f : thickness;
      } else {
        const float dz = -logf(1.f - r()) * fabsf(w.z);
        const float zp = w.z > 0.f ? z + dz : z - dz;
        if (zp > 0.f && zp < thickness) {
          // Scattering in the slab: connect to wi through the coat, then continue.
          const float phase_light = hg_phase(dot(w, -light.wi), m.g);
          const float wt = exit_delta ? 1.f : power_heuristic(light.pdf, phase_light);
          sum += beta * m.medium_albedo * light.weight *
                 (phase_light * wt * transmittance(thickness - zp, light.wi) / light_cos);
          const Vec3 next = hg_sample(w, m.g, {r(), r()});
          if (fabsf(next.z) < kMinCosine) break;
          const float p_next = hg_phase(dot(w, next), m.g);
          beta *= m.medium_albedo;
          w = next;
          z = zp;
          if (!exit_delta && w.z > 0.f) {  // ... and through the coat along the new direction
            const Rgb f_exit = coat_eval(m, coat, -w, wi, mode);
            if (!is_black(f_exit))
              sum += beta * f_exit * (power_heuristic(p_next, coat_pdf(m, coat, wi, -w)) * transmittance(thickness - z, w));
          }
          continue;
        }
        z = zp <= 0.f ? 0.f : thickness;
      }
      if (z == thickness) {  // internal reflection at the coat (transmission out is the connections' job)
        Event e;
        if (!coat_sample_reflection(m, coat, -w, {r(), r()}, mode, &e)) break;
        beta *= e.weight;
        w = e.wi;
        continue;
      }
      // At the base: connect to wi through the coat, then sample the base.
      if (!bottom_delta) {
        const float wt = exit_delta ? 1.f : power_heuristic(light.pdf, base_pdf(m, -w, -light.wi));
        sum += beta * base_eval(m, -w, -light.wi) * light.weight * (wt * transmittance(thickness, light.wi));
      }
      Event e;
      if (!base_sample(m, -w, {r(), r()}, &e)) break;
      beta *= e.weight;
      w = e.wi;
      if (!exit_delta) {
        const Rgb f_exit = coat_eval(m, coat, -w, wi, mode);
        if (!is_black(f_exit)) {
          const float wt = bottom_delta ? 1.f : power_heuristic(e.pdf, coat_pdf(m, coat, wi, -w));
          sum += beta * f_exit * (wt * transmittance(thickness, w));
        }
      }
    }
  }
  return f + sum * (1.f / float(n));
}

// ---- pdf and sample: a mixture of proposal lobes whose density is known exactly.

struct Proposal {
  float mirror = 0.f;  // the smooth coat's mirror reflection: a delta lobe (or everything, for a pure mirror)
  float coat = 0.f;    // a rough coat's reflection lobe (its visible normals)
  float base = 0.f;    // the base: cosine for Lambert, a GGX lobe of roughness base_lobe_alpha for a conductor
  float floor = 0.f;   // a cosine floor under a conductor's lobe
};

// The width of a conductor base's lobe outside: refraction widens it by about the coat's index near
// the normal, and a rough coat adds its own spread.
PS_INLINE float base_lobe_alpha(const Material& m) {
  return clamp_to(m.ior * m.base_alpha + 2.f * (coat_smooth(m) ? 0.f : m.alpha), 0.02f, 1.f);
}
PS_INLINE Material base_lobe(const Material& m) {
  Material c = base_conductor(m);
  c.alpha = base_lobe_alpha(m);
  c.distribution = MicrofacetDistribution::ggx;
  return c;
}

// Lobe probabilities for wo (above the surface): the coat's Fresnel reflectance against what enters
// the slab times the base's albedo (at least 0.05, so the base lobe is never starved).
PS_INLINE Proposal proposal(const Material& m, const Vec3& wo) {
  Proposal p;
  if (pure_mirror(m)) {
    p.mirror = 1.f;
    return p;
  }
  const float f = fresnel_dielectric(fabsf(wo.z), m.ior);
  const float base_albedo =
      m.type == MaterialType::coated_diffuse ? luminance(m.diffuse) : luminance(fresnel_conductor(1.f, m.eta, m.k));
  const float w_coat = f, w_base = (1.f - f) * fmaxf(base_albedo, 0.05f);
  const float w_floor = m.type == MaterialType::coated_conductor ? 0.1f * (w_coat + w_base) : 0.f;
  const float total = w_coat + w_base + w_floor;
  (coat_smooth(m) ? p.mirror : p.coat) = w_coat / total;
  p.base = w_base / total;
  p.floor = w_floor / total;
  return p;
}

PS_INLINE_HOST_ONLY float pdf(const Material& m, const Vec3& wo, const Vec3& wi) {
  if (wo.z < kMinCosine || wi.z < kMinCosine) return 0.f;
  const Proposal p = proposal(m, wo);
  float pdf = p.floor * cosine_hemisphere_pdf(wi);
  if (p.coat > 0.f) pdf += p.coat * coat_pdf(m, coat_material(m), wo, wi);
  if (p.base > 0.f)
    pdf += p.base * (m.type == MaterialType::coated_diffuse ? cosine_hemisphere_pdf(wi)
                                                            : rough_conductor::pdf(base_lobe(m), wo, wi, TransportMode::radiance));
  return pdf;
}

PS_INLINE_HOST_ONLY bool sample(const Material& m, const Vec3& wo, float u_lobe, Point2 u, TransportMode mode, BsdfSample* s) {
  if (wo.z < kMinCosine) return false;
  const Proposal p = proposal(m, wo);
  if (u_lobe < p.mirror) {
    s->wi = Vec3(-wo.x, -wo.y, wo.z);
    s->weight = pure_mirror(m) ? mirror_reflectance(m, wo.z) : Rgb(fresnel_dielectric(wo.z, m.ior) / p.mirror);
    s->pdf_w = p.mirror;
    s->delta = true;
    s->lobe = kLobeSpecular | kLobeReflection;
    s->eta = 1.f;
    return true;
  }
  Vec3 wi;
  if (u_lobe < p.mirror + p.coat) {
    wi = reflect(wo, microfacet::sample_visible_normal(wo, microfacet::clamp_alpha(m.alpha), m.distribution, u));
  } else if (u_lobe < p.mirror + p.coat + p.base && m.type == MaterialType::coated_conductor) {
    wi = reflect(wo, microfacet::sample_visible_normal(wo, base_lobe_alpha(m), MicrofacetDistribution::ggx, u));
  } else {
    wi = square_to_cosine_hemisphere(u);
  }
  if (wi.z < kMinCosine) return false;
  s->wi = wi;
  s->pdf_w = pdf(m, wo, wi);
  if (!(s->pdf_w > 0.f)) return false;
  s->weight = eval(m, wo, wi, mode) * (wi.z / s->pdf_w);
  s->delta = false;
  s->lobe = kLobeGlossy | kLobeReflection;
  s->eta = 1.f;
  return true;
}

PS_INLINE bool has_non_delta(const Material& m) { return !pure_mirror(m); }

}  // namespace pathspace::layered
