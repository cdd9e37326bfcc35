// The host side of lights/emission_cells.h: which mapped area triangles get sampling cells, how
// many, and their weights (the map's mean luminance over each cell, times the light's value).
#pragma once

#include <vector>

#include "pathspace/geometry/shapes.h"
#include "pathspace/lights/light.h"
#include "pathspace/sampling/warps.h"
#include "pathspace/scene/image_texture.h"

namespace pathspace {

// Sets emission_cells and emission_grid of every light (0: sampled by area) and returns the cells
// they point into. A mapped triangle gets n x n cells with n = floor(sqrt(texels / 2)) up to 16,
// where `texels` is the area of its uv triangle in texels, so a cell covers at least two texels;
// one whose map is nearly uniform over it (cell weights within 5%) or covers under 8 texels keeps
// area sampling. Each cell's weight has a floor of 10% of the mean, so no part of the triangle is
// left unsampled where 16 lookups per cell missed a bright texel. `uvs` may be empty.
std::vector<float> build_emission_cells(const std::vector<Triangle>& triangles, const std::vector<Point2>& uvs,
                                        const std::vector<ImageTexture>& textures, std::vector<Light>* lights);

}  // namespace pathspace
