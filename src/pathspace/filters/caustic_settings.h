// Photon-mapped caustics beside path space filtering (Keller, Dahm, Binder 2014, sec. 2.3): what a
// filter asks of the path tracer when light -> specular -> diffuse -> camera paths are to come from
// a photon map with its own shrinking radius instead of from path tracing.
#pragma once

#include <cstdint>

namespace pathspace {

struct CausticSettings {
  // Photons traced per pass and pixel; 0: no photon-mapped caustics. On by default for both filters:
  // without them a filter turns caustics into blotches (docs/hashed-filter.md, "Caustic photons").
  double photons_per_pixel = 0.5;
  float initial_radius = 0.f;  // of the first pass in scene units; <= 0: radius_fraction * bounding radius
  float radius_fraction = 0.01f;
  float alpha = 2.f / 3.f;     // Knaus-Zwicker: r_{i+1}^2 = r_i^2 (i + alpha) / (i + 1)
  // Vertices with a layer smoother than this (or than the vertex selection allows) are links of
  // caustic chains: photons pass them, and only rougher vertices gather (caustic_photons.h).
  float min_roughness = 0.3f;
  // Also photons after one diffuse bounce (light -> links* -> receiver -> links* -> receiver),
  // gathered at every receiver of a camera path: light that reaches a wall off a small lit patch
  // comes from the lights' side, where a camera path's one BSDF sample rarely finds the patch.
  bool one_bounce = false;
  bool enabled() const { return photons_per_pixel > 0.0; }
};

}  // namespace pathspace
