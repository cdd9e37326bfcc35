// MediaView: the device-safe view of a scene's media (media/medium.h) and of which shapes, lights
// and the camera they belong to; part of SceneView. Empty (count 0) in a scene without media, where
// every integrator takes its path without media, unchanged.
#pragma once

#include <cstdint>

#include "pathspace/geometry/interaction.h"
#include "pathspace/media/medium.h"

namespace pathspace {

struct MediaView {
  const Medium* media = nullptr;
  uint32_t count = 0;
  const float* grid_values = nullptr;            // every grid's samples (GridShape::offset)
  const MediumInterface* triangle_interfaces = nullptr;  // per triangle, or null: no triangle is a transition
  const MediumInterface* sphere_interfaces = nullptr;    // per sphere, or null
  const int32_t* light_media = nullptr;          // the medium each light emits into, or null: vacuum
  int32_t camera_medium = kVacuum;

  PS_HD bool any() const { return count > 0; }

  PS_HD MediumInterface interface_at(const SurfaceHit& hit) const {
    const MediumInterface* table = hit.kind == ShapeKind::triangle ? triangle_interfaces : sphere_interfaces;
    return table ? table[hit.prim] : MediumInterface{};
  }
  // The medium a ray leaving `hit` along `d` travels in (media/medium.h, medium_after).
  PS_HD int32_t after(const SurfaceHit& hit, const Vec3& d, int32_t current) const {
    if (count == 0) return current;
    return medium_after(interface_at(hit), hit.ng, d, current);
  }
  PS_HD int32_t light_medium(uint32_t light) const { return light_media ? light_media[light] : kVacuum; }
};

}  // namespace pathspace
