// glTF materials (pbrMetallicRoughness + KHR_materials_emissive_strength, _transmission, _ior) mapped
// onto pathspace's materials, each approximation a warning (docs/scene-files.md, "glTF"):
// * metallic (factor >= 0.5): GGX rough conductor, alpha = roughness^2, with normal-incidence
//   reflectance F0 = baseColor through eta = 1, k = 2 sqrt(F0) / sqrt(1 - F0) (as the pbrt loader's
//   conductor "reflectance");
// * transmission > 0: smooth (alpha < 1e-3) or GGX rough dielectric of the KHR_materials_ior ior
//   (default 1.5), tinted by baseColor;
// * otherwise the pbrt coateddiffuse / Mitsuba plastic approximation: Lambert baseColor * (1 - F0)
//   plus a mirror or Phong (exponent 2/alpha^2 - 2) coat of reflectance F0 = ((ior-1)/(ior+1))^2.
// emissiveFactor * emissiveStrength is the radiance of area lights on the material's triangles.
#pragma once

#include <map>
#include <utility>

#include "pathspace/io/gltf/gltf_context.h"
#include "pathspace/io/gltf/gltf_textures.h"
#include "pathspace/scene/scene.h"

namespace pathspace::gltf {

struct Surface {
  uint32_t material = 0;  // index into Scene::materials
  Rgb emission;           // area light radiance; black: no light
  int32_t emission_texture = -1;  // its emission map (emissiveTexture, sRGB), a scene texture; -1: none
  bool two_sided = false; // doubleSided: emits (and, for diffuse and Phong lobes, reflects) on both sides
};

class Materials {
 public:
  Materials(const Context& c, Scene* scene) : c_(c), scene_(scene), textures_(c, scene) {}
  // For a scene that starts with the materials and textures of the scene `built` was made for (an
  // animation's later frames): those materials are not built (and their images not decoded) again.
  Materials(const Context& c, Scene* scene, std::map<int, Surface> built) : c_(c), scene_(scene), textures_(c, scene), built_(std::move(built)) {}
  // glTF material `index` (-1: glTF's default material), built on first use.
  const Surface& get(int index, const std::string& what);
  const std::map<int, Surface>& built() const { return built_; }

 private:
  Surface build(int index);

  const Context& c_;
  Scene* scene_;
  Textures textures_;
  std::map<int, Surface> built_;
};

}  // namespace pathspace::gltf
