#include "pathspace/scene/scene_media.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "pathspace/base/error.h"

namespace pathspace {

namespace {

void check_coefficient(const Rgb& c, const char* what) {
  for (int i = 0; i < 3; ++i)
    if (!std::isfinite(c[i]) || c[i] < 0.f)
      throw Error(std::string("medium ") + what + " must be finite and >= 0 (got " + std::to_string(c[i]) + ")");
}

void check_g(float g) {
  if (!(g > -1.f && g < 1.f)) throw Error("medium phase asymmetry g must lie in (-1, 1) (got " + std::to_string(g) + ")");
}

void check_grid_values(const std::vector<float>& v, size_t expected, const char* what) {
  if (v.size() != expected)
    throw Error(std::string("medium ") + what + " grid holds " + std::to_string(v.size()) + " values, its size asks for " +
                std::to_string(expected));
  for (float x : v)
    if (!std::isfinite(x) || x < 0.f) throw Error(std::string("medium ") + what + " grid has a value " + std::to_string(x) + " (must be finite and >= 0)");
}

GridShape append_grid(std::vector<float>* store, uint32_t nx, uint32_t ny, uint32_t nz, uint32_t channels,
                      const std::vector<float>& values) {
  GridShape s{nx, ny, nz, channels, uint32_t(store->size())};
  store->insert(store->end(), values.begin(), values.end());
  return s;
}

// The bound of the largest channel over each coarse cell: trilinear interpolation is a convex
// combination of the samples whose support reaches the cell (media/grid_lookup.h).
std::vector<float> majorants_of(const GridShape& s, const float* values, uint32_t mx, uint32_t my, uint32_t mz) {
  const uint32_t res[3] = {s.nx, s.ny, s.nz}, cells[3] = {mx, my, mz};
  std::vector<float> out(size_t(mx) * my * mz, 0.f);
  int lo[3], hi[3];
  for (uint32_t cz = 0; cz < mz; ++cz)
    for (uint32_t cy = 0; cy < my; ++cy)
      for (uint32_t cx = 0; cx < mx; ++cx) {
        const uint32_t c[3] = {cx, cy, cz};
        for (int a = 0; a < 3; ++a) {
          const double from = double(c[a]) / cells[a] * res[a] - 0.5, to = double(c[a] + 1) / cells[a] * res[a] - 0.5;
          lo[a] = std::clamp(int(std::floor(from)), 0, int(res[a]) - 1);
          hi[a] = std::clamp(int(std::floor(to)) + 1, 0, int(res[a]) - 1);
        }
        float m = 0.f;
        for (int z = lo[2]; z <= hi[2]; ++z)
          for (int y = lo[1]; y <= hi[1]; ++y)
            for (int x = lo[0]; x <= hi[0]; ++x) {
              const float* v = values + (size_t(z) * s.ny * s.nx + size_t(y) * s.nx + size_t(x)) * s.channels;
              for (uint32_t k = 0; k < s.channels; ++k) m = std::max(m, v[k]);
            }
        out[(size_t(cz) * my + cy) * mx + cx] = m;
      }
  return out;
}

void check_index(int32_t medium, size_t count, const std::string& where) {
  if (medium != kVacuum && (medium < 0 || size_t(medium) >= count))
    throw Error(where + " names medium " + std::to_string(medium) + " of " + std::to_string(count));
}

}  // namespace

uint32_t SceneMedia::add_homogeneous(const Rgb& sigma_a, const Rgb& sigma_s, float g) {
  check_coefficient(sigma_a, "sigma_a");
  check_coefficient(sigma_s, "sigma_s");
  check_g(g);
  Medium m;
  m.type = MediumType::homogeneous;
  m.sigma_t = sigma_a + sigma_s;
  for (int c = 0; c < 3; ++c) m.albedo[c] = m.sigma_t[c] > 0.f ? sigma_s[c] / m.sigma_t[c] : 0.f;
  m.g = g;
  media.push_back(m);
  return uint32_t(media.size() - 1);
}

uint32_t SceneMedia::add_grid(const GridMediumDesc& d) {
  check_coefficient(d.sigma_t_scale, "sigma_t scale");
  check_coefficient(d.albedo, "albedo");
  check_g(d.g);
  if (d.nx == 0 || d.ny == 0 || d.nz == 0) throw Error("medium grid has a zero size");
  if (d.channels != 1 && d.channels != 3) throw Error("medium grid must have 1 or 3 channels (got " + std::to_string(d.channels) + ")");
  check_grid_values(d.density, size_t(d.nx) * d.ny * d.nz * d.channels, "density");
  for (float x : d.world_to_grid)
    if (!std::isfinite(x)) throw Error("medium grid has a non-finite transform");
  Medium m;
  m.type = MediumType::grid;
  m.sigma_t = d.sigma_t_scale;
  m.albedo = d.albedo;
  m.g = d.g;
  std::copy(std::begin(d.world_to_grid), std::end(d.world_to_grid), m.world_to_grid);
  m.density = append_grid(&grid_values, d.nx, d.ny, d.nz, d.channels, d.density);
  if (d.albedo_nx > 0) {
    check_grid_values(d.albedo_values, size_t(d.albedo_nx) * d.albedo_ny * d.albedo_nz * 3, "albedo");
    m.albedo_grid = append_grid(&grid_values, d.albedo_nx, d.albedo_ny, d.albedo_nz, 3, d.albedo_values);
  }
  const uint32_t mx = std::min(d.nx, kMajorantCells), my = std::min(d.ny, kMajorantCells), mz = std::min(d.nz, kMajorantCells);
  const std::vector<float> bounds = majorants_of(m.density, grid_values.data(), mx, my, mz);
  m.majorants = append_grid(&grid_values, mx, my, mz, 1, bounds);
  media.push_back(m);
  return uint32_t(media.size() - 1);
}

void SceneMedia::bind_triangle(uint32_t triangle, MediumInterface m) {
  if (triangle_interfaces.size() <= triangle) triangle_interfaces.resize(size_t(triangle) + 1);
  triangle_interfaces[triangle] = m;
}
void SceneMedia::bind_sphere(uint32_t sphere, MediumInterface m) {
  if (sphere_interfaces.size() <= sphere) sphere_interfaces.resize(size_t(sphere) + 1);
  sphere_interfaces[sphere] = m;
}
void SceneMedia::bind_light(uint32_t light, int32_t medium) {
  if (light_media.size() <= light) light_media.resize(size_t(light) + 1, kVacuum);
  light_media[light] = medium;
}

void SceneMedia::finalize(size_t triangles, size_t spheres, size_t lights) {
  if (triangle_interfaces.size() > triangles || sphere_interfaces.size() > spheres || light_media.size() > lights)
    throw Error("medium bindings name shapes or lights the scene does not have");
  const size_t n = media.size();
  for (size_t i = 0; i < triangle_interfaces.size(); ++i) {
    check_index(triangle_interfaces[i].inside, n, "triangle " + std::to_string(i));
    check_index(triangle_interfaces[i].outside, n, "triangle " + std::to_string(i));
  }
  for (size_t i = 0; i < sphere_interfaces.size(); ++i) {
    check_index(sphere_interfaces[i].inside, n, "sphere " + std::to_string(i));
    check_index(sphere_interfaces[i].outside, n, "sphere " + std::to_string(i));
  }
  for (size_t i = 0; i < light_media.size(); ++i) check_index(light_media[i], n, "light " + std::to_string(i));
  check_index(camera_medium, n, "the camera");
  if (!triangle_interfaces.empty()) triangle_interfaces.resize(triangles);
  if (!sphere_interfaces.empty()) sphere_interfaces.resize(spheres);
  if (!light_media.empty()) light_media.resize(lights, kVacuum);
}

MediaView SceneMedia::view() const {
  MediaView v;
  v.media = media.empty() ? nullptr : media.data();
  v.count = uint32_t(media.size());
  v.grid_values = grid_values.empty() ? nullptr : grid_values.data();
  v.triangle_interfaces = triangle_interfaces.empty() ? nullptr : triangle_interfaces.data();
  v.sphere_interfaces = sphere_interfaces.empty() ? nullptr : sphere_interfaces.data();
  v.light_media = light_media.empty() ? nullptr : light_media.data();
  v.camera_medium = camera_medium;
  return v;
}

}  // namespace pathspace
