// The media of a Scene (media/medium.h) and their bindings: which media the shapes separate, which
// medium each light emits into, the camera's medium. Loaders fill it through the add_* and bind_*
// helpers, which check their arguments (negative or non-finite coefficients, grids whose value count
// does not match their size); Scene::finalize() checks the indices and view() hands out MediaView.
#pragma once

#include <cstdint>
#include <vector>

#include "pathspace/media/media_view.h"

namespace pathspace {

// A grid medium as a loader reads it (pbrt-v4 uniformgrid / rgbgrid, Mitsuba 3 heterogeneous):
// sigma_t = sigma_t_scale * density (1 or 3 channels per sample), albedo from its own grid (3
// channels, any resolution) or the constant, samples x fastest, then y, then z.
struct GridMediumDesc {
  Rgb sigma_t_scale{1.f};
  Rgb albedo{1.f};
  float g = 0.f;
  float world_to_grid[12] = {1.f, 0.f, 0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 0.f, 1.f, 0.f};
  uint32_t nx = 0, ny = 0, nz = 0, channels = 1;
  std::vector<float> density;
  uint32_t albedo_nx = 0, albedo_ny = 0, albedo_nz = 0;  // 0: the constant albedo
  std::vector<float> albedo_values;                      // 3 per sample
};

class SceneMedia {
 public:
  std::vector<Medium> media;
  std::vector<float> grid_values;
  std::vector<MediumInterface> triangle_interfaces;  // empty, or (after finalize) one per triangle
  std::vector<MediumInterface> sphere_interfaces;    // empty, or one per sphere
  std::vector<int32_t> light_media;                  // empty, or one per light
  int32_t camera_medium = kVacuum;

  // Coarse cells per axis of a grid's majorant grid (at most; never more than the grid's samples).
  static constexpr uint32_t kMajorantCells = 16;

  // pbrt-v4's and Mitsuba's parameterisations: absorption and scattering, or extinction and albedo.
  uint32_t add_homogeneous(const Rgb& sigma_a, const Rgb& sigma_s, float g);
  uint32_t add_grid(const GridMediumDesc& grid);

  void bind_triangle(uint32_t triangle, MediumInterface m);
  void bind_sphere(uint32_t sphere, MediumInterface m);
  void bind_light(uint32_t light, int32_t medium);

  bool empty() const { return media.empty(); }
  // Checks every medium index and pads the bindings to the scene's shapes and lights. Throws Error.
  void finalize(size_t triangles, size_t spheres, size_t lights);
  MediaView view() const;
};

}  // namespace pathspace
