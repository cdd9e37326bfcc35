// The one place where a hit's material meets its textures: a copy of the material record with the
// textured reflectances multiplied in at the hit's uv. Every integrator evaluates BSDFs (and the
// hashed filter's albedo demodulation, eq. 9) on this copy, so texture detail is never averaged.
#pragma once

#include "pathspace/geometry/interaction.h"
#include "pathspace/scene/scene_view.h"

namespace pathspace {

PS_INLINE bool has_textures(const Material& m) { return m.diffuse_texture >= 0 || m.glossy_texture >= 0 || m.specular_texture >= 0; }

// A copy of material record `material` with each textured reflectance multiplied by lookup(texture):
// the one place that knows which reflectances carry textures (point lookups here, pixel footprints
// in texture_footprint.h).
template <typename Lookup>
PS_INLINE Material textured_material(const SceneView& scene, uint32_t material, const Lookup& lookup) {
  Material m = scene.materials[material];
  if (m.diffuse_texture >= 0) m.diffuse *= lookup(scene.textures[m.diffuse_texture]);
  if (m.glossy_texture >= 0) m.glossy *= lookup(scene.textures[m.glossy_texture]);
  if (m.specular_texture >= 0) m.specular *= lookup(scene.textures[m.specular_texture]);
  return m;
}

struct PointTextureLookup {
  Point2 uv;
  PS_HD Rgb operator()(const TextureView& t) const { return texture_lookup(t, uv); }
};

PS_INLINE Material shading_material(const SceneView& scene, uint32_t material, Point2 uv) {
  return textured_material(scene, material, PointTextureLookup{uv});
}

PS_INLINE Material shading_material(const SceneView& scene, const SurfaceHit& hit) {
  return shading_material(scene, hit.material, hit.uv);
}

// The kernels' form: the scene's own record when the material has no textures (untextured scenes
// pay no copy per bounce), else the textured copy written to *storage.
PS_INLINE const Material& shading_material(const SceneView& scene, uint32_t material, Point2 uv, Material* storage) {
  const Material& m = scene.materials[material];
  if (!has_textures(m)) return m;
  *storage = shading_material(scene, material, uv);
  return *storage;
}

PS_INLINE const Material& shading_material(const SceneView& scene, const SurfaceHit& hit, Material* storage) {
  return shading_material(scene, hit.material, hit.uv, storage);
}

}  // namespace pathspace
