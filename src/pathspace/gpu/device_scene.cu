#include "pathspace/gpu/device_scene.h"

#include <cstring>

namespace pathspace::gpu {

template <typename T>
const T* DeviceScene::upload(const T* host, size_t n) {
  if (host == nullptr || n == 0) return nullptr;
  DeviceBuffer<unsigned char> buffer;
  buffer.upload(reinterpret_cast<const unsigned char*>(host), n * sizeof(T));
  bytes_ += buffer.bytes();
  arrays_.push_back(std::move(buffer));
  return reinterpret_cast<const T*>(arrays_.back().data());
}

namespace {
DiscreteView device_discrete(const DiscreteView& host, auto&& upload) {
  DiscreteView d = host;
  d.cdf = upload(host.cdf, size_t(host.n) + 1);
  d.pmf = upload(host.pmf, size_t(host.n));
  return d;
}
}  // namespace

DeviceScene::DeviceScene(const Scene& scene) {
  const SceneView h = scene.view();
  const size_t vertices = scene.positions.size();
  view_ = h;  // scalars, the camera and the bounds as they are; every pointer replaced below
  view_.positions = upload(h.positions, vertices);
  view_.uvs = upload(h.uvs, h.uvs ? vertices : 0);
  view_.normals = upload(h.normals, h.normals ? vertices : 0);
  view_.positions_end = upload(h.positions_end, h.positions_end ? vertices : 0);  // motion blur
  view_.normals_end = upload(h.normals_end, h.normals_end ? vertices : 0);
  view_.triangles = upload(h.triangles, h.num_triangles);
  view_.spheres = upload(h.spheres, h.num_spheres);
  view_.materials = upload(h.materials, h.num_materials);
  view_.lights = upload(h.lights, h.num_lights);
  view_.emission_cells = upload(h.emission_cells, h.num_emission_cells);
  // Textures: each view's texels first, then the array of views pointing at them.
  std::vector<TextureView> textures(h.textures, h.textures + h.num_textures);
  for (TextureView& t : textures) {
    if (t.bytes) {  // an 8-bit texture: its bytes and its 256 byte values
      t.bytes = upload(t.bytes, 3 * size_t(t.width) * size_t(t.height));
      t.byte_values = upload(t.byte_values, 256);
    } else {
      t.texels = upload(t.texels, size_t(t.width) * size_t(t.height));
    }
  }
  view_.textures = upload(textures.data(), textures.size());
  auto up = [this](const auto* p, size_t n) { return upload(p, n); };
  view_.light_selection = device_discrete(h.light_selection, up);
  if (h.light_tree.active) {
    view_.light_tree.nodes = upload(h.light_tree.nodes, h.light_tree.num_nodes);
    view_.light_tree.leaf_position = upload(h.light_tree.leaf_position, h.num_lights);
    view_.light_tree.infinite = upload(h.light_tree.infinite, h.light_tree.num_infinite);
  }
  // Participating media (docs/media.md): the media, their grids and majorants, the bindings.
  const MediaView& hm = h.media;
  view_.media.media = upload(hm.media, hm.count);
  view_.media.grid_values = upload(hm.grid_values, scene.media.grid_values.size());
  view_.media.triangle_interfaces = upload(hm.triangle_interfaces, hm.triangle_interfaces ? h.num_triangles : 0);
  view_.media.sphere_interfaces = upload(hm.sphere_interfaces, hm.sphere_interfaces ? h.num_spheres : 0);
  view_.media.light_media = upload(hm.light_media, hm.light_media ? h.num_lights : 0);
  EnvironmentMapView& env = view_.environment_map;
  env.texels = upload(h.environment_map.texels, size_t(h.environment_map.width) * size_t(h.environment_map.height));
  const Piecewise2DView& dist = h.environment_map.distribution;
  if (dist.valid()) {
    const size_t W = size_t(dist.width), H = size_t(dist.height);
    env.distribution.row_cdf = upload(dist.row_cdf, H + 1);
    env.distribution.cell_cdf = upload(dist.cell_cdf, H * (W + 1));
    env.distribution.cell_pdf = upload(dist.cell_pdf, H * W);
  }
}

}  // namespace pathspace::gpu
