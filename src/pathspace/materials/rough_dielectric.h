// Rough dielectric (GGX or Beckmann, microfacet_distribution.h) after Walter et al. 2007,
// "Microfacet Models for Refraction through Rough Surfaces": reflection (eq. 20) plus transmission
// (eq. 21), the lobe chosen by the Fresnel term of the sampled visible microfacet (Heitz 2018). wo and
// wi may lie on either side (wo.z < 0: inside the glass, ior = n_inside / n_outside). `specular`
// tints both lobes. alpha < 1e-3 is clamped to 1e-3. Transmission in TransportMode::radiance carries
// (eta_wo / eta_wi)^2 (Veach 1997 §5.2); the importance-mode BSDF is the adjoint,
// f_importance(wo, wi) = f_radiance(wi, wo).
#pragma once

#include "pathspace/materials/bsdf_sample.h"
#include "pathspace/materials/fresnel.h"
#include "pathspace/materials/material.h"
#include "pathspace/materials/microfacet_distribution.h"
#include "pathspace/sampling/warps.h"

namespace pathspace::rough_dielectric {

// The microfacet normal (m.z > 0) joining wo and wi, with everything eval and pdf share.
struct HalfVector {
  Vec3 h;
  bool reflect = true;
  float etap = 1.f;  // n_wi_side / n_wo_side (1 for reflection)
  float fresnel = 1.f;
  bool valid = false;
};

PS_INLINE HalfVector half_vector(const Material& m, const Vec3& wo, const Vec3& wi) {
  HalfVector r;
  if (fabsf(wo.z) < kMinCosine || fabsf(wi.z) < kMinCosine) return r;
  r.reflect = wo.z * wi.z > 0.f;
  r.etap = r.reflect ? 1.f : (wo.z > 0.f ? m.ior : 1.f / m.ior);
  // Generalized half vector (Walter eq. 13 for reflection, eq. 16 for transmission).
  Vec3 h = wo + wi * r.etap;
  const float len2 = length_squared(h);
  if (!(len2 > 0.f)) return r;
  h = h / sqrtf(len2);
  if (h.z < 0.f) h = -h;
  // Back-facing microfacet configurations have no density (G1's sidedness term).
  if (dot(wo, h) * wo.z <= 0.f || dot(wi, h) * wi.z <= 0.f) return r;
  r.h = h;
  // For transmission F is evaluated from the optically thinner side: the same value for (wo, wi)
  // and (wi, wo), and no cancellation near the critical angle on the denser side.
  const Vec3& wf = (r.reflect || (wo.z > 0.f) == (m.ior >= 1.f)) ? wo : wi;
  r.fresnel = fresnel_dielectric(dot(wf, h), m.ior);
  r.valid = true;
  return r;
}

// (wi.h + wo.h / etap)^2: the transmission Jacobian's denominator (Walter eq. 17 divided by n_wi^2).
PS_INLINE float transmission_denominator(const Vec3& wo, const Vec3& wi, const HalfVector& hv) {
  return sqr(dot(wi, hv.h) + dot(wo, hv.h) / hv.etap);
}

// Refraction of wo about the microfacet normal h: wi = -wo / etap + (cos_o / etap - sign(cos_o) cos_t) h,
// etap = n_wi_side / n_wo_side. False under total internal reflection (Fresnel 1 up to rounding) and
// when wi does not cross the macro surface.
PS_INLINE bool refract_about(const Vec3& wo, const Vec3& h, float ior, Vec3* wi, float* etap) {
  const float cos_o = dot(wo, h);
  *etap = cos_o > 0.f ? ior : 1.f / ior;
  const float sin2_t = (1.f - cos_o * cos_o) / sqr(*etap);
  if (sin2_t >= 1.f) return false;
  const float cos_t = sqrtf(1.f - sin2_t);
  *wi = -wo / *etap + h * (cos_o / *etap - copysignf(cos_t, cos_o));
  return wi->z * wo.z < 0.f;
}

PS_INLINE Rgb eval(const Material& m, const Vec3& wo, const Vec3& wi, TransportMode mode) {
  const HalfVector hv = half_vector(m, wo, wi);
  if (!hv.valid) return {};
  const float alpha = microfacet::clamp_alpha(m.alpha);
  const float dg = microfacet::d(hv.h, alpha, m.distribution) * microfacet::g2(wo, wi, alpha, m.distribution);
  const float cos_oi = fabsf(wo.z * wi.z);
  if (hv.reflect) return m.specular * (hv.fresnel * dg / (4.f * cos_oi));
  // Walter eq. 21, with n_wi^2 divided out of numerator and denominator.
  float ft = (1.f - hv.fresnel) * dg * fabsf(dot(wi, hv.h) * dot(wo, hv.h)) /
             (cos_oi * transmission_denominator(wo, wi, hv));
  if (mode == TransportMode::radiance) ft /= sqr(hv.etap);
  return m.specular * ft;
}

// Visible-normal pdf times the lobe probability and the half-vector Jacobian (Walter eqs. 14, 17).
PS_INLINE float pdf(const Material& m, const Vec3& wo, const Vec3& wi, TransportMode) {
  const HalfVector hv = half_vector(m, wo, wi);
  if (!hv.valid) return 0.f;
  const float alpha = microfacet::clamp_alpha(m.alpha);
  const float pdf_h = microfacet::visible_normal_pdf(wo, hv.h, alpha, m.distribution);
  if (hv.reflect) return hv.fresnel * pdf_h / (4.f * fabsf(dot(wo, hv.h)));
  return (1.f - hv.fresnel) * pdf_h * fabsf(dot(wi, hv.h)) / transmission_denominator(wo, wi, hv);
}

PS_INLINE bool sample(const Material& m, const Vec3& wo, float u_lobe, Point2 u, TransportMode mode, BsdfSample* s) {
  if (fabsf(wo.z) < kMinCosine) return false;
  const float alpha = microfacet::clamp_alpha(m.alpha);
  const Vec3 h = microfacet::sample_visible_normal(wo, alpha, m.distribution, u);
  const float cos_o = dot(wo, h);  // same sign as wo.z
  const float fresnel = fresnel_dielectric(cos_o, m.ior);
  Vec3 wi;
  if (u_lobe < fresnel) {
    wi = reflect(wo, h);
    if (wi.z * wo.z <= 0.f) return false;
    s->lobe = kLobeGlossy | kLobeReflection;
    s->eta = 1.f;
  } else {
    float etap;
    if (!refract_about(wo, h, m.ior, &wi, &etap)) return false;
    s->lobe = kLobeGlossy | kLobeTransmission;
    s->eta = etap;
  }
  s->wi = wi;
  s->delta = false;
  // Evaluated from (wo, wi) so that the sample, pdf() and eval() agree exactly.
  s->pdf_w = pdf(m, wo, wi, mode);
  if (!(s->pdf_w > 0.f)) return false;
  s->weight = eval(m, wo, wi, mode) * (fabsf(wi.z) / s->pdf_w);  // = tint G2 / G1(wo) [/ etap^2]
  return true;
}

}  // namespace pathspace::rough_dielectric
