// Per-pixel guide buffers (normal, albedo, position, pixel footprint) of a scene's first camera hits,
// for the screen-space à-trous baseline of `pathspace study psf` (atrous_filter.h). The study casts
// one ray through each pixel centre itself, through the Accel contract, rather than asking the
// integrators for debug images: the baseline is a reference point of the study, not a render option.
#pragma once

#include <cstdint>
#include <vector>

#include "pathspace/math/rgb.h"
#include "pathspace/math/vec3.h"

namespace pathspace {
class Accel;
class Scene;
}  // namespace pathspace

namespace pathspace::study {

struct GuideBuffers {
  int width = 0, height = 0;
  std::vector<uint8_t> hit;      // 1: the pixel centre's ray hits a surface; 0: the other fields are zero
  std::vector<Vec3> normal;      // shading normal, facing the camera
  std::vector<Rgb> albedo;       // diffuse + glossy + specular reflectance at the hit (textures applied)
  std::vector<Vec3> position;    // world space
  std::vector<float> footprint;  // world-space width of one pixel at the hit's distance

  size_t size() const { return hit.size(); }
  // Every pixel hits, with the given normal and albedo, on a plane facing the camera at unit footprint.
  static GuideBuffers uniform(int width, int height, Vec3 normal, Rgb albedo);
};

// The first hits of the pixel centres of the scene's camera, at its image size.
GuideBuffers render_guide_buffers(const Scene& scene, const Accel& accel);

}  // namespace pathspace::study
