// The scene's environment light: constant radiance `value` sampled uniformly over the sphere, or,
// when the scene has an environment image, value (the scale) times the image, importance-sampled
// by the image's distribution (lights/environment_map.h). Every integrator evaluates escaping rays
// and their MIS densities through these two functions, so NEE and BSDF sampling agree.
#pragma once

#include "pathspace/lights/environment_map.h"
#include "pathspace/scene/scene_view.h"

namespace pathspace {

// Radiance arriving along -w, i.e. seen when looking in world direction w.
PS_INLINE Rgb environment_radiance(const SceneView& scene, const Light& l, const Vec3& w) {
  return scene.environment_map.texels ? l.value * envmap_radiance(scene.environment_map, w) : l.value;
}

// Solid-angle density with which sample_environment picks the direction w.
PS_INLINE float environment_pdf(const SceneView& scene, const Vec3& w) {
  return scene.environment_map.texels ? envmap_pdf(scene.environment_map, w) : uniform_sphere_pdf();
}

// A direction towards the environment; returns the radiance from there (black: no sample).
PS_INLINE Rgb sample_environment(const SceneView& scene, const Light& l, Point2 u, Vec3* w, float* pdf_w) {
  if (!scene.environment_map.texels) {
    *w = square_to_uniform_sphere(u);
    *pdf_w = uniform_sphere_pdf();
    return l.value;
  }
  return l.value * envmap_sample(scene.environment_map, u, w, pdf_w);
}

}  // namespace pathspace
