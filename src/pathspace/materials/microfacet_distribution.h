// The microfacet distribution of a rough conductor or rough dielectric, chosen per material:
// GGX (microfacet.h) or Beckmann (microfacet_beckmann.h). The BSDFs need D, the height-correlated
// G2 = 1 / (1 + Lambda(wo) + Lambda(wi)) (Heitz 2014 eq. 99), and visible-normal sampling with its
// density D_w(m) = G1(w) max(0, w.m) D(m) / w.z (Heitz 2018 eq. 3), the same formulas for both.
#pragma once

#include "pathspace/materials/material.h"
#include "pathspace/materials/microfacet.h"
#include "pathspace/materials/microfacet_beckmann.h"

namespace pathspace::microfacet {

PS_INLINE float d(const Vec3& m, float alpha, MicrofacetDistribution dist) {
  return dist == MicrofacetDistribution::beckmann ? beckmann_d(m, alpha) : ggx_d(m, alpha);
}

PS_INLINE float g2(const Vec3& wo, const Vec3& wi, float alpha, MicrofacetDistribution dist) {
  if (dist == MicrofacetDistribution::ggx) return ggx_g2(wo, wi, alpha);
  return 1.f / (1.f + beckmann_lambda(wo, alpha) + beckmann_lambda(wi, alpha));
}

PS_INLINE Vec3 sample_visible_normal(const Vec3& w, float alpha, MicrofacetDistribution dist, Point2 u) {
  return dist == MicrofacetDistribution::beckmann ? beckmann_sample_visible_normal(w, alpha, u) : ggx_sample_visible_normal(w, alpha, u);
}

PS_INLINE float visible_normal_pdf(Vec3 w, const Vec3& m, float alpha, MicrofacetDistribution dist) {
  if (dist == MicrofacetDistribution::ggx) return ggx_visible_normal_pdf(w, m, alpha);
  if (w.z < 0.f) w = -w;
  const float wm = dot(w, m);
  if (wm <= 0.f || w.z <= 0.f) return 0.f;
  return wm * beckmann_d(m, alpha) / ((1.f + beckmann_lambda(w, alpha)) * w.z);
}

}  // namespace pathspace::microfacet
