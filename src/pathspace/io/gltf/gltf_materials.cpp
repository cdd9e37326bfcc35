// glTF material mapping (see gltf_materials.h for the model and docs/scene-files.md for the warnings).
#include "pathspace/io/gltf/gltf_materials.h"

#include <algorithm>
#include <cmath>
#include <set>

namespace pathspace::gltf {

namespace {

// A number from an extension object ("KHR_materials_ior": {"ior": 1.4}); `fallback` when absent.
float extension_number(const Context& c, const tinygltf::ExtensionMap& ext, const char* extension, const char* key, float fallback,
                       const std::string& what) {
  const auto it = ext.find(extension);
  if (it == ext.end() || !it->second.IsObject() || !it->second.Has(key)) return fallback;
  const tinygltf::Value& v = it->second.Get(key);
  const double x = v.IsNumber() ? v.GetNumberAsDouble() : NAN;
  if (!std::isfinite(x)) c.fail(what + ".extensions." + extension + "." + key + " is not a finite number");
  return float(x);
}

// The glTF schema bounds every material factor to [0, 1] (emission is scaled by its own extension);
// a value outside is an error, not clamped into a colour the author did not write.
float unit_factor(const Context& c, double x, const std::string& what) {
  if (!std::isfinite(x)) c.fail(what + " is not a finite number");
  if (x < 0.0 || x > 1.0) c.fail(what + " = " + std::to_string(x) + " is outside [0, 1]");
  return float(x);
}

Rgb unit_factor_rgb(const Context& c, const std::vector<double>& v, size_t expected, const std::string& what) {
  if (v.size() != expected) c.fail(what + " has " + std::to_string(v.size()) + " numbers; expected " + std::to_string(expected));
  for (size_t i = 0; i < v.size(); ++i) unit_factor(c, v[i], what + "[" + std::to_string(i) + "]");
  return Rgb(float(v[0]), float(v[1]), float(v[2]));
}

Rgb clamp01(const Rgb& v) { return Rgb(std::clamp(v.r, 0.f, 1.f), std::clamp(v.g, 0.f, 1.f), std::clamp(v.b, 0.f, 1.f)); }

}  // namespace

const Surface& Materials::get(int index, const std::string& what) {
  if (index != -1) check_index(c_, index, c_.model.materials.size(), what);
  if (const auto it = built_.find(index); it != built_.end()) return it->second;
  return built_.emplace(index, build(index)).first->second;
}

Surface Materials::build(int index) {
  static const tinygltf::Material kDefault;  // glTF's default: white, metallic 1, roughness 1
  const tinygltf::Material& mt = index < 0 ? kDefault : c_.model.materials[size_t(index)];
  const std::string name = index < 0 ? std::string("the default material") : element("materials", size_t(index));
  const std::string pbr_name = name + ".pbrMetallicRoughness";
  const tinygltf::PbrMetallicRoughness& pbr = mt.pbrMetallicRoughness;

  const Rgb base = unit_factor_rgb(c_, pbr.baseColorFactor, 4, pbr_name + ".baseColorFactor");
  float metallic = unit_factor(c_, pbr.metallicFactor, pbr_name + ".metallicFactor");
  float roughness = unit_factor(c_, pbr.roughnessFactor, pbr_name + ".roughnessFactor");
  if (pbr.metallicRoughnessTexture.index >= 0) {  // roughness in G, metallic in B, linear data
    const std::string what = pbr_name + ".metallicRoughnessTexture";
    if (const auto mean = textures_.mean(pbr.metallicRoughnessTexture.index, LdrEncoding::linear, what)) {
      roughness *= std::clamp(mean->g, 0.f, 1.f);
      metallic *= std::clamp(mean->b, 0.f, 1.f);
      c_.warn(what + " replaced by its mean (roughness " + std::to_string(roughness) + ", metallic " + std::to_string(metallic) + ")");
    }
  }
  const float alpha = roughness * roughness;
  const float ior = extension_number(c_, mt.extensions, "KHR_materials_ior", "ior", 1.5f, name);
  const float eta = ior >= 1.f ? ior : 1.5f;
  if (ior < 1.f) c_.warn(name + ".extensions.KHR_materials_ior.ior = " + std::to_string(ior) + " not supported; 1.5 used");
  const float transmission = unit_factor(c_, extension_number(c_, mt.extensions, "KHR_materials_transmission", "transmissionFactor", 0.f, name),
                                         name + ".extensions.KHR_materials_transmission.transmissionFactor");
  const bool base_textured = pbr.baseColorTexture.index >= 0;
  const std::string base_tex = pbr_name + ".baseColorTexture";
  // Conductors and dielectrics have no texture slot: a baseColor texture enters as its mean colour.
  auto untextured_base = [&](const char* model) {
    if (!base_textured) return base;
    const auto mean = textures_.mean(pbr.baseColorTexture.index, LdrEncoding::srgb, base_tex);
    if (!mean) return base;
    c_.warn(base_tex + " on a " + model + " replaced by its mean colour");
    return clamp01(base * *mean);
  };

  Material m;
  if (metallic >= 0.5f) {
    if (metallic < 1.f) c_.warn(pbr_name + ".metallicFactor " + std::to_string(metallic) + " rounded to 1 (conductor)");
    const Rgb f0 = untextured_base("conductor");
    Rgb k;
    for (int i = 0; i < 3; ++i) k[i] = 2.f * std::sqrt(std::min(f0[i], 0.9999f)) / std::sqrt(1.f - std::min(f0[i], 0.9999f));
    m = make_rough_conductor(std::max(alpha, 1e-3f), Rgb(1.f), k);
    if (transmission > 0.f) c_.warn(name + ": transmission on a metal ignored");
  } else if (transmission > 0.f) {
    if (transmission < 1.f) c_.warn(name + ".extensions.KHR_materials_transmission.transmissionFactor " + std::to_string(transmission) + " rounded to 1");
    if (metallic > 0.f) c_.warn(pbr_name + ".metallicFactor " + std::to_string(metallic) + " rounded to 0 (dielectric)");
    const Rgb tint = untextured_base("dielectric");
    m = alpha < 1e-3f ? make_glass(eta, tint) : make_rough_dielectric(alpha, eta, tint);
  } else {
    if (metallic > 0.f) c_.warn(pbr_name + ".metallicFactor " + std::to_string(metallic) + " rounded to 0 (dielectric)");
    const float f0 = ((eta - 1.f) / (eta + 1.f)) * ((eta - 1.f) / (eta + 1.f));
    m.diffuse = base * (1.f - f0);
    if (base_textured) m.diffuse_texture = textures_.texture(pbr.baseColorTexture, LdrEncoding::srgb, base_tex);
    if (alpha < 1e-3f) {
      m.specular = Rgb(f0);
    } else {
      m.glossy = Rgb(f0);
      m.exponent = std::max(1.f, 2.f / (alpha * alpha) - 2.f);
    }
    c_.warn(name + ": dielectric base approximated as Lambert (baseColor * (1 - F0)) + " + std::string(alpha < 1e-3f ? "mirror" : "Phong") +
            " coat of reflectance F0 = " + std::to_string(f0));
  }
  m.two_sided = mt.doubleSided;

  Surface s;
  s.two_sided = mt.doubleSided;
  s.emission = unit_factor_rgb(c_, mt.emissiveFactor.empty() ? std::vector<double>{0, 0, 0} : mt.emissiveFactor, 3, name + ".emissiveFactor");
  const float strength = extension_number(c_, mt.extensions, "KHR_materials_emissive_strength", "emissiveStrength", 1.f, name);
  if (strength < 0.f) c_.fail(name + ".extensions.KHR_materials_emissive_strength.emissiveStrength is negative");
  s.emission = s.emission * strength;
  // The emission map multiplies emissiveFactor at the surface's uv (an unreadable image: the factor
  // alone, with textures_' warning).
  if (mt.emissiveTexture.index >= 0 && !is_black(s.emission))
    s.emission_texture = textures_.texture(mt.emissiveTexture, LdrEncoding::srgb, name + ".emissiveTexture");
  if (!(std::min({s.emission.r, s.emission.g, s.emission.b}) >= 0.f)) c_.fail(name + ".emissiveFactor is negative");

  if (mt.normalTexture.index >= 0) c_.warn(name + ".normalTexture ignored");
  if (mt.occlusionTexture.index >= 0) c_.warn(name + ".occlusionTexture ignored");
  if (mt.alphaMode != "OPAQUE") c_.warn(name + ".alphaMode " + mt.alphaMode + " not supported; opaque");
  if (transmission > 0.f && mt.extensions.count("KHR_materials_transmission")) {
    const tinygltf::Value& t = mt.extensions.at("KHR_materials_transmission");
    if (t.IsObject() && t.Has("transmissionTexture")) c_.warn(name + ".extensions.KHR_materials_transmission.transmissionTexture ignored");
  }
  static const std::set<std::string> kKnown = {"KHR_materials_ior", "KHR_materials_transmission", "KHR_materials_emissive_strength"};
  for (const auto& [ext, value] : mt.extensions)
    if (!kKnown.count(ext)) c_.warn(name + ".extensions." + ext + " ignored");
  s.material = scene_->add_material(m);
  return s;
}

}  // namespace pathspace::gltf
