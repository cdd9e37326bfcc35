// The "standard" material: Lambert diffuse + normalised Phong + one smooth specular lobe (a mirror
// without Fresnel, or a smooth dielectric with exact Fresnel). This is exactly the material model
// of the built-in Cornell scenes (docs/scenes.md §4.1), generalised to any sum of these lobes.
//
// Lobe selection probabilities are proportional to the lobes' luminance albedo (the dielectric's
// split by Fresnel); eval/pdf cover the non-delta lobes only (a delta lobe has no density).
// Unlike SmallVCM (docs/scenes.md §4.2) a Phong sample below the horizon gets zero weight and ends the path.
#pragma once

#include "pathspace/materials/bsdf_sample.h"
#include "pathspace/materials/fresnel.h"
#include "pathspace/materials/material.h"
#include "pathspace/math/frame.h"
#include "pathspace/sampling/warps.h"

namespace pathspace::standard {

// Phong lobes are zero when the lobe cosine is at or below this (docs/scenes.md §4.1).
inline constexpr float kMinPhongCosine = 1e-3f;

struct LobeProbabilities {
  float diffuse = 0.f, glossy = 0.f, reflect = 0.f, refract = 0.f;
  float fresnel = 1.f;  // dielectric F at wo (1 for a mirror)
};

PS_INLINE LobeProbabilities lobe_probabilities(const Material& m, const Vec3& wo) {
  LobeProbabilities p;
  const bool upper = wo.z >= kMinCosine;
  const float wd = upper ? luminance(m.diffuse) : 0.f;
  const float wg = upper ? luminance(m.glossy) : 0.f;
  const float ws = luminance(m.specular);
  float wr = ws, wt = 0.f;
  if (m.ior > 0.f) {
    p.fresnel = fresnel_dielectric(wo.z, m.ior);
    wr = ws * p.fresnel;
    wt = ws * (1.f - p.fresnel);
  }
  const float total = wd + wg + wr + wt;
  if (total <= 0.f) return p;
  p.diffuse = wd / total;
  p.glossy = wg / total;
  p.reflect = wr / total;
  p.refract = wt / total;
  return p;
}

PS_INLINE float phong_lobe_cosine(const Vec3& wo, const Vec3& wi) { return dot(Vec3(-wo.x, -wo.y, wo.z), wi); }

PS_INLINE bool both_above(const Vec3& wo, const Vec3& wi) { return wo.z >= kMinCosine && wi.z >= kMinCosine; }

// f (without cosine) of the non-delta lobes. Symmetric in wo, wi.
PS_INLINE Rgb eval(const Material& m, const Vec3& wo, const Vec3& wi) {
  if (!both_above(wo, wi)) return {};
  Rgb f = m.diffuse * kInvPi;
  if (!is_black(m.glossy)) {
    const float c = phong_lobe_cosine(wo, wi);
    if (c > kMinPhongCosine) f += m.glossy * ((m.exponent + 2.f) * kInvTwoPi * powf(c, m.exponent));
  }
  return f;
}

// The pdf of wi given the lobe probabilities p = lobe_probabilities(m, wo): sample has them at hand.
PS_INLINE float pdf_given(const Material& m, const LobeProbabilities& p, const Vec3& wo, const Vec3& wi) {
  if (!both_above(wo, wi)) return 0.f;
  float result = p.diffuse * wi.z * kInvPi;
  if (p.glossy > 0.f) {
    const float c = phong_lobe_cosine(wo, wi);
    if (c > kMinPhongCosine) result += p.glossy * (m.exponent + 1.f) * kInvTwoPi * powf(c, m.exponent);
  }
  return result;
}

PS_INLINE float pdf(const Material& m, const Vec3& wo, const Vec3& wi) {
  return both_above(wo, wi) ? pdf_given(m, lobe_probabilities(m, wo), wo, wi) : 0.f;
}

PS_INLINE bool sample(const Material& m, const Vec3& wo, float u_lobe, Point2 u, TransportMode mode, BsdfSample* s) {
  const LobeProbabilities p = lobe_probabilities(m, wo);
  if (u_lobe < p.diffuse + p.glossy) {
    if (u_lobe < p.diffuse) {
      s->wi = square_to_cosine_hemisphere(u);
      s->lobe = kLobeDiffuse | kLobeReflection;
    } else {
      const Frame lobe_frame(Vec3(-wo.x, -wo.y, wo.z));
      s->wi = lobe_frame.to_world(square_to_power_cosine(u, m.exponent));
      s->lobe = kLobeGlossy | kLobeReflection;
    }
    s->delta = false;
    s->eta = 1.f;
    s->pdf_w = pdf_given(m, p, wo, s->wi);
    if (s->pdf_w <= 0.f) return false;  // below the horizon: the path ends (no SmallVCM quirk)
    s->weight = eval(m, wo, s->wi) * (fabsf(s->wi.z) / s->pdf_w);
    return true;
  }
  s->delta = true;
  if (u_lobe < p.diffuse + p.glossy + p.reflect) {
    s->wi = Vec3(-wo.x, -wo.y, wo.z);
    s->lobe = kLobeSpecular | kLobeReflection;
    s->pdf_w = p.reflect;
    s->eta = 1.f;
    s->weight = m.specular * (p.fresnel / p.reflect);
    return p.reflect > 0.f;
  }
  if (p.refract <= 0.f) return false;
  Vec3 wt;
  if (!refract_local(wo, m.ior, &wt)) return false;
  s->wi = wt;
  s->lobe = kLobeSpecular | kLobeTransmission;
  s->pdf_w = p.refract;
  // eta of the wi side over the wo side.
  s->eta = wo.z > 0.f ? m.ior : 1.f / m.ior;
  float scale = (1.f - p.fresnel) / p.refract;
  // Radiance is compressed by (eta_wo / eta_wi)^2 when crossing; importance is not (adjoint BSDF).
  if (mode == TransportMode::radiance) scale /= s->eta * s->eta;
  s->weight = m.specular * scale;
  return true;
}

PS_INLINE bool has_non_delta(const Material& m) { return !is_black(m.diffuse) || !is_black(m.glossy); }

}  // namespace pathspace::standard
