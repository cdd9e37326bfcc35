// The host side of lights/emission_cells.h: which mapped area triangles get sampling cells, how
// many, and their weights (the map's mean luminance over each cell, times the light's value).
#pragma once

#include <vector>

#include "pathspace/geometry/shapes.h"
#include "pathspace/geometry/surface_attributes.h"
#include "pathspace/lights/light.h"
#include "pathspace/sampling/warps.h"
#include "pathspace/scene/image_texture.h"
#include "pathspace/scene/texture.h"

namespace pathspace {

// Calls f with the map's value at side x side stratified points (uniform by area) of the part of
// triangle `tri` whose corners c0, c1, c2 are given in barycentrics (weight of vertex 0, weight of
// vertex 1) times `scale`: the lookups that a cell's weight and a mapped light's power
// (Scene::light_power) average. `uvs` may be null (triangle_uv's stand-in).
template <typename F>
void for_each_map_lookup(const Triangle& tri, const Point2* uvs, const TextureView& map, Point2 c0, Point2 c1, Point2 c2,
                         float scale, int side, F f) {
  for (int y = 0; y < side; ++y)
    for (int x = 0; x < side; ++x) {
      const Point2 s = square_to_triangle_barycentric({(float(x) + 0.5f) / float(side), (float(y) + 0.5f) / float(side)});
      const float s2 = 1.f - s.x - s.y;
      const float a = (c0.x * s.x + c1.x * s.y + c2.x * s2) / scale, c = (c0.y * s.x + c1.y * s.y + c2.y * s2) / scale;
      f(texture_lookup(map, triangle_uv(tri, uvs, c, 1.f - a - c)));
    }
}

// Sets emission_cells and emission_grid of every light (0: sampled by area) and returns the cells
// they point into. A mapped triangle gets n x n cells with n = floor(sqrt(texels / 2)) up to 16,
// where `texels` is the area of its uv triangle in texels, so a cell covers at least two texels;
// one whose map is nearly uniform over it (cell weights within 5%) or covers under 8 texels keeps
// area sampling. Each cell's weight has a floor of 10% of the mean, so no part of the triangle is
// left unsampled where 16 lookups per cell missed a bright texel. `uvs` may be empty.
std::vector<float> build_emission_cells(const std::vector<Triangle>& triangles, const std::vector<Point2>& uvs,
                                        const std::vector<ImageTexture>& textures, std::vector<Light>* lights);

}  // namespace pathspace
