// Rough conductor (Walter et al. 2007 eq. 20 with exact complex Fresnel), GGX or Beckmann
// (microfacet_distribution.h), sampled with visible normals (Heitz 2018; Heitz & d'Eon 2014). One-sided: zero unless wo and wi are both above the surface (bsdf.h mirrors
// two-sided materials). alpha < 1e-3 is clamped to 1e-3 (microfacet.h).
// f = F(wi.h) D(h) G2(wo, wi) / (4 wo.z wi.z), symmetric in wo and wi, so both transport modes agree.
#pragma once

#include "pathspace/materials/bsdf_sample.h"
#include "pathspace/materials/fresnel.h"
#include "pathspace/materials/material.h"
#include "pathspace/materials/microfacet_distribution.h"
#include "pathspace/sampling/warps.h"

namespace pathspace::rough_conductor {

PS_INLINE bool both_above(const Vec3& wo, const Vec3& wi) { return wo.z >= kMinCosine && wi.z >= kMinCosine; }

PS_INLINE Rgb eval(const Material& m, const Vec3& wo, const Vec3& wi, TransportMode) {
  if (!both_above(wo, wi)) return {};
  const float alpha = microfacet::clamp_alpha(m.alpha);
  const Vec3 h = normalize(wo + wi);
  const float d = microfacet::d(h, alpha, m.distribution);
  const float g = microfacet::g2(wo, wi, alpha, m.distribution);
  return fresnel_conductor(dot(wi, h), m.eta, m.k) * (d * g / (4.f * wo.z * wi.z)) * m.tint;
}

// Visible-normal pdf times the reflection Jacobian 1 / (4 |wo.h|) (Walter 2007 eq. 14).
PS_INLINE float pdf(const Material& m, const Vec3& wo, const Vec3& wi, TransportMode) {
  if (!both_above(wo, wi)) return 0.f;
  const float alpha = microfacet::clamp_alpha(m.alpha);
  const Vec3 h = normalize(wo + wi);
  const float wo_h = dot(wo, h);
  if (wo_h <= 0.f) return 0.f;
  return microfacet::visible_normal_pdf(wo, h, alpha, m.distribution) / (4.f * wo_h);
}

PS_INLINE bool sample(const Material& m, const Vec3& wo, float, Point2 u, TransportMode mode, BsdfSample* s) {
  if (wo.z < kMinCosine) return false;
  const float alpha = microfacet::clamp_alpha(m.alpha);
  const Vec3 h = microfacet::sample_visible_normal(wo, alpha, m.distribution, u);
  const Vec3 wi = reflect(wo, h);
  if (wi.z < kMinCosine) return false;  // reflected below the horizon (multiple scattering ignored)
  s->wi = wi;
  s->pdf_w = pdf(m, wo, wi, mode);
  if (!(s->pdf_w > 0.f)) return false;
  s->weight = eval(m, wo, wi, mode) * (wi.z / s->pdf_w);  // = F G2 / G1(wo)
  s->lobe = kLobeGlossy | kLobeReflection;
  s->delta = false;
  s->eta = 1.f;
  return true;
}

}  // namespace pathspace::rough_conductor
