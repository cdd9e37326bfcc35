// Material records: plain data selected by MaterialType, evaluated by a switch in bsdf.h.
// All BSDF functions work in the local shading frame (z = normal), with wo towards the camera side
// and wi towards the light side, both pointing away from the surface (docs/conventions.md).
#pragma once

#include <cstdint>

#include "pathspace/math/rgb.h"

namespace pathspace {

enum class MaterialType : uint8_t {
  standard,          // sum of Lambert diffuse + normalised Phong + one smooth specular lobe (mirror or glass)
  rough_conductor,   // microfacet metal (GGX or Beckmann), visible-normal sampling
  rough_dielectric,  // microfacet glass (Walter et al. 2007; GGX or Beckmann), visible-normal sampling
  coated_diffuse,    // dielectric coat over a Lambertian base (materials/layered_bsdf.h; pbrt-v4 coateddiffuse)
  coated_conductor,  // dielectric coat over a conductor (materials/layered_bsdf.h; pbrt-v4 coatedconductor)
  interface,         // no surface: it only bounds media (pbrt-v4's "interface", Mitsuba's null BSDF);
                     // paths pass it unchanged (media/medium.h), it scatters nothing
};

enum class TransportMode : uint8_t { radiance, importance };

// The microfacet normal distribution of rough_conductor and rough_dielectric
// (materials/microfacet_distribution.h).
enum class MicrofacetDistribution : uint8_t { ggx, beckmann };

struct Material {
  MaterialType type = MaterialType::standard;
  // Diffuse and Phong lobes are one-sided by default (zero from the back, as in the Cornell
  // scenes); two_sided mirrors them to the side of wo.
  bool two_sided = false;
  MicrofacetDistribution distribution = MicrofacetDistribution::ggx;  // rough_conductor / rough_dielectric

  // standard
  Rgb diffuse;             // Lambert albedo rho_d
  Rgb glossy;              // Phong rho_p, f = rho_p (n + 2) / (2 pi) cos^n(alpha)
  float exponent = 1.f;    // Phong exponent n
  Rgb specular;            // smooth specular reflectance rho_m (mirror, or glass tint)
  float ior = 0.f;         // 0: the specular lobe is a mirror (no Fresnel); > 0: smooth dielectric

  // rough_conductor / rough_dielectric
  float alpha = 0.1f;      // microfacet roughness (GGX: alpha = perceptual roughness^2)
  Rgb eta{1.f, 1.f, 1.f};  // conductor: real part of the complex IOR (per channel)
  Rgb k;                   // conductor: imaginary part
  // rough_conductor: a factor on the whole reflection (Mitsuba's specular_reflectance, Tungsten's
  // albedo; 1 = the Fresnel term alone, as pbrt-v4's conductor).
  Rgb tint{1.f, 1.f, 1.f};
  // rough_dielectric uses `ior` (inside / outside) and `specular` as the tint.

  // coated_diffuse / coated_conductor: a coat of index `ior` and roughness `alpha` (< 1e-3: smooth)
  // over the base, `diffuse` (Lambert) or a conductor of `eta`, `k` (relative to the coat) and
  // roughness `base_alpha`; between them a slab `thickness` mean free paths deep that scatters with
  // albedo `medium_albedo` (black: it only absorbs) and Henyey-Greenstein `g`. eval runs `n_samples`
  // random walks of at most `max_depth` events.
  float base_alpha = 0.f;
  float thickness = 0.01f;
  Rgb medium_albedo;
  float g = 0.f;
  uint16_t max_depth = 10;
  uint16_t n_samples = 1;

  // Image textures (indices into SceneView::textures, -1 = none) multiply diffuse, glossy and
  // specular at the hit's uv; scene/shading_material.h applies them, once per hit.
  int32_t diffuse_texture = -1;
  int32_t glossy_texture = -1;
  int32_t specular_texture = -1;

  // Cutout opacity (Mitsuba's mask, pbrt-v4's shape alpha; scene/surface_opacity.h): the fraction
  // of the rays reaching the surface that hit it, `opacity` times the first channel of
  // `opacity_texture` (-1 = none); the others pass through as if nothing were there. Applies to
  // triangles that do not emit (validation warns where it is ignored).
  float opacity = 1.f;
  int32_t opacity_texture = -1;
};

// Convenience constructors.
inline Material make_diffuse(const Rgb& albedo) {
  Material m;
  m.diffuse = albedo;
  return m;
}
inline Material make_mirror(const Rgb& reflectance = Rgb(1.f)) {
  Material m;
  m.specular = reflectance;
  return m;
}
inline Material make_glass(float ior, const Rgb& tint = Rgb(1.f)) {
  Material m;
  m.specular = tint;
  m.ior = ior;
  return m;
}
inline Material make_phong(const Rgb& diffuse, const Rgb& glossy, float exponent) {
  Material m;
  m.diffuse = diffuse;
  m.glossy = glossy;
  m.exponent = exponent;
  return m;
}
inline Material make_rough_conductor(float alpha, const Rgb& eta, const Rgb& k) {
  Material m;
  m.type = MaterialType::rough_conductor;
  m.alpha = alpha;
  m.eta = eta;
  m.k = k;
  m.two_sided = false;
  return m;
}
inline Material make_rough_dielectric(float alpha, float ior, const Rgb& tint = Rgb(1.f)) {
  Material m;
  m.type = MaterialType::rough_dielectric;
  m.alpha = alpha;
  m.ior = ior;
  m.specular = tint;
  return m;
}

}  // namespace pathspace
