// Mitsuba BSDF conversion (see mitsuba_materials.h). Roughness `alpha` is Mitsuba's microfacet
// alpha directly (no remapping), with its `distribution` (Beckmann, Mitsuba's default, or GGX:
// materials/microfacet_distribution.h). Index of refraction = int_ior / ext_ior.
#include "pathspace/io/mitsuba/mitsuba_materials.h"

#include <algorithm>
#include <cmath>

#include "pathspace/io/mitsuba/mitsuba_object.h"
#include "pathspace/io/named_spectra.h"
#include "pathspace/materials/fresnel.h"

namespace pathspace::mitsuba {

namespace {

float ior_param(const Object& o, const std::string& name, float fallback) {
  const Property* p = o.find(name);
  if (!p) return fallback;
  if (p->tag == "float") return float(o.get_float(name, fallback));
  const std::string v = o.get_string(name, "");
  float ior = fallback;
  if (!find_named_ior(v, &ior)) throw Error(o.doc().loc(p->node), "unknown index of refraction '" + v + "'");
  return ior;
}

float eta_of(const Object& o, float int_default) {
  const float eta = ior_param(o, "int_ior", int_default) / ior_param(o, "ext_ior", 1.000277f);
  if (!(eta > 0.f) || !std::isfinite(eta)) throw Error(o.loc(), o.title() + ": int_ior / ext_ior must be positive");
  return eta;
}

// The roughness of a rough material, and its microfacet distribution (Mitsuba's default: Beckmann)
// for the materials that are microfacet models (plastic's Phong coat already follows Beckmann's
// exponent mapping and ignores it).
float alpha_of(const Object& o, LoadWarnings* w, MicrofacetDistribution* distribution = nullptr) {
  const float a = float(o.get_float("alpha", 0.1));
  const float u = float(o.get_float("alpha_u", a)), v = float(o.get_float("alpha_v", a));
  if (u != v) w->add(o.loc(), o.title() + ": anisotropic roughness approximated by sqrt(alpha_u * alpha_v)");
  const std::string dist = o.get_string("distribution", "beckmann");
  if (dist != "ggx" && dist != "beckmann") throw Error(o.loc(), o.title() + ": distribution must be beckmann or ggx");
  if (distribution) *distribution = dist == "ggx" ? MicrofacetDistribution::ggx : MicrofacetDistribution::beckmann;
  o.ignore({"sample_visible"});  // visible normals are always sampled
  const float alpha = std::sqrt(std::max(0.f, u) * std::max(0.f, v));
  if (!std::isfinite(alpha)) throw Error(o.loc(), o.title() + ": alpha must be finite");
  return alpha;
}

Material conductor(const Object& o, const std::string& folder, LoadWarnings* w) {
  const bool rough = o.type() == "roughconductor";
  const std::string name = o.get_string("material", o.doc().legacy() ? "Cu" : "none");
  Rgb eta(1.f), k(200.f);  // "none": a perfect mirror (|r| = 1 - 1e-4, the pbrt loader's reflectance route)
  if (name != "none" && !(find_named_spectrum("metal-" + name + "-eta", &eta) && find_named_spectrum("metal-" + name + "-k", &k))) {
    w->add(o.loc(), o.title() + ": conductor '" + name + "' has no RGB fit in pathspace (Cu, Au, Ag, Al, CuZn, MgO, TiO2); using Al");
    find_named_spectrum("metal-Al-eta", &eta);
    find_named_spectrum("metal-Al-k", &k);
  }
  eta = o.get_rgb("eta", eta, folder, w, SpectrumUse::unbounded);
  k = o.get_rgb("k", k, folder, w, SpectrumUse::unbounded);
  // Mitsuba's eta and k are relative to the exterior: a given ext_eta (a number or a named index)
  // divides them. Without one the exterior is vacuum (Mitsuba's default, air at 1.000277, would
  // change them by 0.03%).
  if (o.has("ext_eta")) {
    const float ext = ior_param(o, "ext_eta", 1.f);
    if (!(ext > 0.f) || !std::isfinite(ext)) throw Error(o.loc(), o.title() + ": ext_eta must be positive");
    eta = eta * (1.f / ext);
    k = k * (1.f / ext);
  }
  MicrofacetDistribution distribution = MicrofacetDistribution::ggx;
  Material m = make_rough_conductor(rough ? alpha_of(o, w, &distribution) : 0.f, eta, k);
  m.distribution = distribution;
  m.tint = o.get_rgb("specular_reflectance", Rgb(1.f), folder, w);  // scales the reflection, as in Mitsuba
  return m;
}

Material dielectric(const Object& o, const std::string& folder, LoadWarnings* w) {
  const float eta = eta_of(o, 1.5046f);  // Mitsuba's default int_ior is "bk7"
  const Rgb tint = o.get_rgb("specular_transmittance", Rgb(1.f), folder, w);
  if (o.has("specular_reflectance") && o.get_rgb("specular_reflectance", Rgb(1.f), folder, w) != Rgb(1.f))
    w->add(o.loc(), o.title() + ": specular_reflectance tint is not supported; ignored");
  if (o.type() == "thindielectric") {
    w->add(o.loc(), "thindielectric approximated by a smooth dielectric interface (a thin slab does not refract)");
    return make_glass(eta, tint);
  }
  MicrofacetDistribution distribution = MicrofacetDistribution::ggx;
  const float alpha = o.type() == "roughdielectric" ? alpha_of(o, w, &distribution) : 0.f;
  if (alpha < 1e-3f) return make_glass(eta, tint);
  Material m = make_rough_dielectric(alpha, eta, tint);
  m.distribution = distribution;
  return m;
}

// Mitsuba's plastic and roughplastic: a dielectric coat over a Lambertian base with internal
// reflections and no absorption, i.e. the layered BSDF with a slab of zero thickness. For a smooth
// coat Mitsuba's "nonlinear" model, f = rho (1 - F_i)(1 - F_o) / (pi eta^2 (1 - rho Fdr)), is that
// BSDF exactly; its default linear model divides by (1 - Fdr) instead, which equals the exact model
// with the base albedo rho' = rho / (1 - Fdr (1 - rho)) (Fdr: internal_diffuse_fresnel).
Material plastic(const Object& o, const std::string& folder, TextureBinding* textures, LoadWarnings* w) {
  Material m;
  m.type = MaterialType::coated_diffuse;
  m.ior = eta_of(o, 1.49f);  // Mitsuba's default int_ior is "polypropylene"
  m.alpha = o.type() == "roughplastic" ? alpha_of(o, w, &m.distribution) : 0.f;
  m.thickness = 1e-6f;  // nothing absorbed between coat and base
  m.max_depth = 64;     // the internal reflections' series converges long before
  m.diffuse = textured_rgb(o, "diffuse_reflectance", Rgb(0.5f), folder, textures, w, &m.diffuse_texture);
  if (!o.get_bool("nonlinear", false)) {
    if (m.diffuse_texture >= 0)
      w->add(o.loc(), o.title() + ": the linear model (nonlinear=false) with a textured diffuse_reflectance is approximated by the nonlinear one");
    else {
      const float fdr = float(internal_diffuse_fresnel(m.ior));
      for (int c = 0; c < 3; ++c) m.diffuse[c] = m.diffuse[c] / (1.f - fdr * (1.f - m.diffuse[c]));
    }
  }
  if (o.has("specular_reflectance") && o.get_rgb("specular_reflectance", Rgb(1.f), folder, w) != Rgb(1.f))
    w->add(o.loc(), o.title() + ": specular_reflectance tint is not supported; ignored");
  m.two_sided = false;
  return m;
}

Material make_bsdf_nested(const Document& doc, const pugi::xml_node& node, const NamedMaterials& named, const std::string& folder,
                          LoadWarnings* w, TextureBinding* textures, int depth);

}  // namespace

Material default_bsdf() { return make_diffuse(Rgb(0.5f)); }

Material make_bsdf(const Document& doc, const pugi::xml_node& node, const NamedMaterials& named, const std::string& folder,
                   LoadWarnings* w, TextureBinding* textures) {
  return make_bsdf_nested(doc, node, named, folder, w, textures, 0);
}

namespace {

// Mitsuba's mask: the nested BSDF with cutout opacity (scene/surface_opacity.h), a float or a bitmap
// read as a float texture; nested masks multiply.
void mask(const Object& o, const std::string& folder, TextureBinding* textures, LoadWarnings* w, Material* m) {
  int32_t texture = -1;
  const Rgb value = textured_rgb(o, "opacity", Rgb(0.5f), folder, textures, w, &texture, ImageContent::scalar);
  const float opacity = (value.r + value.g + value.b) / 3.f;
  if (!(opacity >= 0.f && opacity <= 1.f)) throw Error(o.loc(), o.title() + ": opacity must lie in [0, 1]");
  if (texture >= 0 && m->opacity_texture >= 0) {
    w->add(o.loc(), o.title() + ": a textured mask inside another textured mask: only the outer texture is used");
  }
  m->opacity *= opacity;
  if (texture >= 0) m->opacity_texture = texture;
}

Material make_bsdf_nested(const Document& doc, const pugi::xml_node& node, const NamedMaterials& named, const std::string& folder,
                          LoadWarnings* w, TextureBinding* textures, int depth) {
  // Wrappers nest; a bound keeps hostile files from exhausting the stack.
  if (depth > 16) throw Error(doc.loc(node), "BSDFs nested more than 16 deep");
  if (std::string(node.name()) == "ref") {
    const std::string id = doc.attr(node, "id");
    const auto it = named.find(id);
    if (it == named.end()) throw Error(doc.loc(node), "<ref id=\"" + id + "\"> names no <bsdf> defined before it");
    return it->second;
  }
  const Object o(doc, node);
  const std::string& t = o.type();
  Material m;
  if (t == "twosided" || t == "bumpmap" || t == "normalmap" || t == "mask") {
    std::vector<pugi::xml_node> inner = o.children("bsdf");
    for (const pugi::xml_node& r : o.children("ref")) inner.push_back(r);
    if (inner.empty()) throw Error(o.loc(), o.title() + " needs a nested <bsdf> or <ref>");
    if (inner.size() > 1) w->add(o.loc(), o.title() + ": different front and back BSDFs are not supported; the first is used on both sides");
    m = make_bsdf_nested(doc, inner[0], named, folder, w, textures, depth + 1);
    if (t == "twosided") {
      m.two_sided = true;
    } else if (t == "mask") {
      mask(o, folder, textures, w, &m);
    } else {
      w->add(o.loc(), o.title() + " is not supported: its nested BSDF is used alone");
      o.ignore_all();
    }
  } else if (t == "diffuse") {
    int32_t texture = -1;
    m = make_diffuse(textured_rgb(o, "reflectance", Rgb(0.5f), folder, textures, w, &texture));
    m.diffuse_texture = texture;
  } else if (t == "conductor" || t == "roughconductor") {
    m = conductor(o, folder, w);
  } else if (t == "dielectric" || t == "roughdielectric" || t == "thindielectric") {
    m = dielectric(o, folder, w);
  } else if (t == "plastic" || t == "roughplastic") {
    m = plastic(o, folder, textures, w);
  } else if (t == "null") {  // no surface: the shape only bounds media (mitsuba_media.h)
    m.type = MaterialType::interface;
  } else {
    w->add(o.loc(), "BSDF type '" + t + "' not supported; using grey diffuse 0.5");
    o.ignore_all();
    m = default_bsdf();
  }
  o.warn_unused(w);
  return m;
}

}  // namespace

}  // namespace pathspace::mitsuba
