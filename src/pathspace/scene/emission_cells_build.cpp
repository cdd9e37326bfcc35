// Sampling cells of mapped area triangles (scene/emission_cells_build.h).
#include "pathspace/scene/emission_cells_build.h"

#include <algorithm>
#include <cmath>

#include "pathspace/lights/emission_cells.h"

namespace pathspace {
namespace {

constexpr uint32_t kMaxGrid = 16;
constexpr int kLookupSide = 4;               // 4 x 4 stratified lookups per cell
constexpr float kWeightFloor = 0.1f;         // of the mean cell weight
constexpr float kUniformWithin = 1.05f;      // max / min cell weight below which area sampling stays
constexpr size_t kMaxFloats = size_t(1) << 24;  // 64 MB of cells per scene; later lights stay uniform

// The cell grid a triangle's uv footprint warrants (0: too few texels for cells).
uint32_t grid_for(const Point2 uv[3], const ImageTexture& texture) {
  const float du1 = uv[1].x - uv[0].x, dv1 = uv[1].y - uv[0].y, du2 = uv[2].x - uv[0].x, dv2 = uv[2].y - uv[0].y;
  const double texels = 0.5 * std::fabs(double(du1) * dv2 - double(dv1) * du2) * double(texture.width) * double(texture.height);
  if (!(texels >= 8.0)) return 0;
  return uint32_t(std::min(double(kMaxGrid), std::floor(std::sqrt(texels / 2.0))));
}

// Mean luminance of value * map over every cell of an n x n grid (0 past the far edge).
std::vector<float> cell_weights(const Triangle& tri, const Point2* uvs, const TextureView& map, const Rgb& value, uint32_t n) {
  std::vector<float> w(emission_cell_count(n), 0.f);
  for (uint32_t cell = 0; cell < w.size(); ++cell) {
    if (!emission_cell_inside(n, cell)) continue;
    double sum = 0.0;
    for_each_map_lookup(tri, uvs, map, emission_cell_corner(n, cell, 0), emission_cell_corner(n, cell, 1),
                        emission_cell_corner(n, cell, 2), float(n), kLookupSide,
                        [&](const Rgb& texel) { sum += luminance(value * texel); });
    w[cell] = float(std::max(0.0, sum) / (kLookupSide * kLookupSide));
  }
  return w;
}

}  // namespace

std::vector<float> build_emission_cells(const std::vector<Triangle>& triangles, const std::vector<Point2>& uvs,
                                        const std::vector<ImageTexture>& textures, std::vector<Light>* lights) {
  std::vector<float> cells;
  for (Light& l : *lights) {
    l.emission_cells = 0;
    l.emission_grid = 0;
    if (l.type != LightType::area_triangle || l.texture < 0) continue;
    const Triangle& tri = triangles[l.shape];
    const bool has_uvs = uvs.size() > tri.v[0] && uvs.size() > tri.v[1] && uvs.size() > tri.v[2];
    const Point2 corner_uv[3] = {has_uvs ? uvs[tri.v[0]] : Point2{0.f, 0.f}, has_uvs ? uvs[tri.v[1]] : Point2{1.f, 0.f},
                                 has_uvs ? uvs[tri.v[2]] : Point2{1.f, 1.f}};  // triangle_uv's stand-in without uvs
    const ImageTexture& texture = textures[size_t(l.texture)];
    const uint32_t n = grid_for(corner_uv, texture);
    if (n < 2 || cells.size() + emission_cell_floats(n) > kMaxFloats) continue;
    std::vector<float> w = cell_weights(tri, has_uvs ? uvs.data() : nullptr, texture.view(), l.value, n);
    float lo = INFINITY, hi = 0.f;
    double total = 0.0;
    for (uint32_t cell = 0; cell < w.size(); ++cell) {
      if (!emission_cell_inside(n, cell)) continue;
      lo = std::min(lo, w[cell]);
      hi = std::max(hi, w[cell]);
      total += w[cell];
    }
    if (!(hi > 0.f) || !std::isfinite(hi) || hi <= lo * kUniformWithin) continue;
    const float floor = kWeightFloor * float(total / (double(n) * n));
    for (uint32_t cell = 0; cell < w.size(); ++cell)
      if (emission_cell_inside(n, cell)) w[cell] += floor;
    const DiscreteDistribution d(w);
    const DiscreteView v = d.view();
    l.emission_cells = uint32_t(cells.size());
    l.emission_grid = n;
    cells.insert(cells.end(), v.pmf, v.pmf + v.n);
    cells.insert(cells.end(), v.cdf, v.cdf + v.n + 1);
  }
  return cells;
}

}  // namespace pathspace
