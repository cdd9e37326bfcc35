// BSDF dispatch: one switch over MaterialType (no virtual calls; device-safe, docs/architecture.md §4).
// Directions are local to the shading frame; f excludes the cosine; pdfs are per solid angle.
// Two-sided materials are evaluated in the frame mirrored to wo's side.
#pragma once

#include "pathspace/materials/layered_bsdf.h"
#include "pathspace/materials/rough_conductor.h"
#include "pathspace/materials/rough_dielectric.h"
#include "pathspace/materials/standard_material.h"

namespace pathspace {

namespace detail {
// Whether the material is evaluated mirrored to wo's side when wo is below the surface: two-sided
// ones, but for dielectrics, whose two sides are the two media.
PS_INLINE bool mirrors_to_wo_side(const Material& m) {
  switch (m.type) {
    case MaterialType::standard: return m.two_sided && !(m.ior > 0.f);
    case MaterialType::rough_dielectric: return false;
    default: return m.two_sided;
  }
}
PS_INLINE bool flip_for_two_sided(const Material& m, Vec3* wo, Vec3* wi) {
  if (!mirrors_to_wo_side(m) || wo->z >= 0.f) return false;
  wo->z = -wo->z;
  if (wi) wi->z = -wi->z;
  return true;
}
}  // namespace detail

PS_INLINE Rgb bsdf_eval(const Material& m, Vec3 wo, Vec3 wi, TransportMode mode) {
  detail::flip_for_two_sided(m, &wo, &wi);
  switch (m.type) {
    case MaterialType::standard: return standard::eval(m, wo, wi);
    case MaterialType::rough_conductor: return rough_conductor::eval(m, wo, wi, mode);
    case MaterialType::rough_dielectric: return rough_dielectric::eval(m, wo, wi, mode);
    case MaterialType::coated_diffuse:
    case MaterialType::coated_conductor: return layered::eval(m, wo, wi, mode);
    case MaterialType::interface: break;
  }
  return {};
}

PS_INLINE float bsdf_pdf(const Material& m, Vec3 wo, Vec3 wi, TransportMode mode) {
  detail::flip_for_two_sided(m, &wo, &wi);
  switch (m.type) {
    case MaterialType::standard: return standard::pdf(m, wo, wi);
    case MaterialType::rough_conductor: return rough_conductor::pdf(m, wo, wi, mode);
    case MaterialType::rough_dielectric: return rough_dielectric::pdf(m, wo, wi, mode);
    case MaterialType::coated_diffuse:
    case MaterialType::coated_conductor: return layered::pdf(m, wo, wi);
    case MaterialType::interface: break;
  }
  return 0.f;
}

// u_lobe picks a lobe, u samples within it.
PS_INLINE bool bsdf_sample(const Material& m, Vec3 wo, float u_lobe, Point2 u, TransportMode mode, BsdfSample* s) {
  const bool flipped = detail::flip_for_two_sided(m, &wo, nullptr);
  bool ok = false;
  switch (m.type) {
    case MaterialType::standard: ok = standard::sample(m, wo, u_lobe, u, mode, s); break;
    case MaterialType::rough_conductor: ok = rough_conductor::sample(m, wo, u_lobe, u, mode, s); break;
    case MaterialType::rough_dielectric: ok = rough_dielectric::sample(m, wo, u_lobe, u, mode, s); break;
    case MaterialType::coated_diffuse:
    case MaterialType::coated_conductor: ok = layered::sample(m, wo, u_lobe, u, mode, s); break;
    case MaterialType::interface: break;
  }
  if (ok && flipped) s->wi.z = -s->wi.z;
  return ok;
}

// True when the material has a lobe that eval/pdf can see (NEE and MIS are worthwhile).
PS_INLINE bool bsdf_has_non_delta(const Material& m) {
  switch (m.type) {
    case MaterialType::standard: return standard::has_non_delta(m);
    case MaterialType::coated_diffuse:
    case MaterialType::coated_conductor: return layered::has_non_delta(m);
    case MaterialType::interface: return false;
    default: return true;
  }
}

// Whether both lobes of a smooth dielectric can be followed here, each as its own branch: a material
// with only delta lobes, reflection and refraction both possible at wo. *p_reflect is the reflection
// lobe's probability: bsdf_sample takes reflection for u_lobe below it, refraction above, and the
// sample's weight times its pdf_w is that branch's weight when both branches are traced.
PS_INLINE bool bsdf_delta_branches(const Material& m, const Vec3& wo, float* p_reflect) {
  if (m.type != MaterialType::standard || !(m.ior > 0.f) || standard::has_non_delta(m)) return false;
  const standard::LobeProbabilities p = standard::lobe_probabilities(m, wo);
  *p_reflect = p.reflect;
  return p.reflect > 0.f && p.refract > 0.f;
}

}  // namespace pathspace
