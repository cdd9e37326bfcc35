// Layer decomposition of a BSDF for path space filtering (Binder et al. 2021, sec. 3.1.2 and eq. 9).
// A filterable material is split into layers f = sum_l f_l; each layer is f_l = albedo_l * g_l with
// the albedo (the f_r(w_r, x) factor of eq. 9) kept out of the voxel average, so texture and colour
// detail is not blurred. Materials with a Dirac delta lobe or rough transmission are not filterable.
#pragma once

#include "pathspace/materials/bsdf.h"

namespace pathspace {

inline constexpr int kMaxBsdfLayers = 2;
// kLayerMedium: a vertex in a participating medium (integrators/pt/pt_kernel.h, pt_on_medium), so
// that filters never average it with surface vertices.
enum BsdfLayerId : uint8_t { kLayerDiffuse = 0, kLayerGlossy = 1, kLayerMedium = 2 };

struct BsdfLayers {
  int count = 0;                  // 0: not filterable
  uint8_t id[kMaxBsdfLayers] = {};
  Rgb albedo[kMaxBsdfLayers];     // demodulation factor (may be 0 in a channel)
  float roughness[kMaxBsdfLayers] = {};  // 1 = Lambertian; GGX-alpha-like for glossy lobes
};

// Phong exponent n as an equivalent microfacet roughness (Walter et al. 2007, alpha_b = sqrt(2/(n+2))).
PS_INLINE float phong_roughness(float exponent) { return sqrtf(2.f / (exponent + 2.f)); }

PS_INLINE BsdfLayers bsdf_layers(const Material& m) {
  BsdfLayers l;
  switch (m.type) {
    case MaterialType::standard:
      if (!is_black(m.specular)) return l;  // a delta lobe cannot be averaged
      if (!is_black(m.diffuse)) {
        l.id[l.count] = kLayerDiffuse;
        l.albedo[l.count] = m.diffuse;
        l.roughness[l.count++] = 1.f;
      }
      if (!is_black(m.glossy)) {
        l.id[l.count] = kLayerGlossy;
        l.albedo[l.count] = m.glossy;
        l.roughness[l.count++] = phong_roughness(m.exponent);
      }
      return l;
    case MaterialType::rough_conductor:
      l.id[0] = kLayerGlossy;
      l.albedo[0] = fresnel_conductor(1.f, m.eta, m.k);
      l.roughness[0] = m.alpha;
      l.count = 1;
      return l;
    case MaterialType::rough_dielectric:
    case MaterialType::coated_diffuse:  // the random walk's estimate is not a sum of demodulable layers
    case MaterialType::coated_conductor:
    case MaterialType::interface: return l;
  }
  return l;
}

// The layers' f (without cosine), in the order of bsdf_layers(m); they sum to bsdf_eval.
PS_INLINE void bsdf_eval_layers(const Material& m, const BsdfLayers& layers, Vec3 wo, Vec3 wi, TransportMode mode,
                                Rgb f[kMaxBsdfLayers]) {
  detail::flip_for_two_sided(m, &wo, &wi);
  for (int i = 0; i < layers.count; ++i) f[i] = Rgb();
  if (m.type == MaterialType::rough_conductor) {
    f[0] = rough_conductor::eval(m, wo, wi, mode);
    return;
  }
  if (!standard::both_above(wo, wi)) return;
  for (int i = 0; i < layers.count; ++i) {
    if (layers.id[i] == kLayerDiffuse) {
      f[i] = m.diffuse * kInvPi;
    } else {
      const float c = standard::phong_lobe_cosine(wo, wi);
      if (c > standard::kMinPhongCosine) f[i] = m.glossy * ((m.exponent + 2.f) * kInvTwoPi * powf(c, m.exponent));
    }
  }
}

}  // namespace pathspace
