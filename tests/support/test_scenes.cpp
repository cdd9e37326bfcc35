#include "support/test_scenes.h"

#include <vector>

#include "pathspace/scene/builtin_scenes.h"

namespace pathspace::testing {

namespace {
// Adds quad a b c d, ordered so its geometric normal points along `inward`.
void add_facing_quad(Scene& s, Vec3 a, Vec3 b, Vec3 c, Vec3 d, const Vec3& inward, uint32_t material, const Rgb& le) {
  if (dot(cross(b - a, c - a), inward) < 0.f) std::swap(b, d);
  s.add_quad(a, b, c, d, material, le);
}

void inside_camera(Scene& s, int resolution) {
  s.camera = make_perspective_camera(Vec3(0.1f, -0.2f, 0.05f), Vec3(0.3f, 1.f, 0.2f), Vec3(0, 0, 1), 90.f, resolution, resolution);
  s.ray_epsilon = 1e-4f;
  s.max_path_segments = 1 << 20;  // effectively unlimited: Russian roulette ends paths
}
}  // namespace

Scene make_furnace_box(float emission, float albedo, int resolution) {
  Scene s;
  const uint32_t m = s.add_material(make_diffuse(Rgb(albedo)));
  const Rgb le(emission);
  for (int axis = 0; axis < 3; ++axis) {
    for (int side = -1; side <= 1; side += 2) {
      // Face at coordinate `side` on `axis`, with the other two axes spanning [-1, 1].
      const int u = (axis + 1) % 3, v = (axis + 2) % 3;
      Vec3 corners[4];
      const float us[4] = {-1, 1, 1, -1}, vs[4] = {-1, -1, 1, 1};
      for (int k = 0; k < 4; ++k) {
        corners[k][axis] = float(side);
        corners[k][u] = us[k];
        corners[k][v] = vs[k];
      }
      Vec3 inward;
      inward[axis] = float(-side);
      add_facing_quad(s, corners[0], corners[1], corners[2], corners[3], inward, m, le);
    }
  }
  inside_camera(s, resolution);
  s.finalize();
  return s;
}

Scene make_sphere_with_point_light(float radius, float albedo, float intensity, int resolution) {
  Scene s;
  const uint32_t m = s.add_material(make_diffuse(Rgb(albedo)));
  s.add_sphere(Vec3(0, 0, 0), radius, m, Rgb(), /*inward_normals=*/true);
  s.add_point_light(Vec3(0, 0, 0), Rgb(intensity));
  inside_camera(s, resolution);
  s.finalize();
  return s;
}

Scene make_emissive_sphere(float radius, float emission, float albedo, int resolution) {
  Scene s;
  const uint32_t m = s.add_material(make_diffuse(Rgb(albedo)));
  s.add_sphere(Vec3(0, 0, 0), radius, m, Rgb(emission), /*inward_normals=*/true);
  inside_camera(s, resolution);
  s.finalize();
  return s;
}

Scene make_plane_under_sky(float albedo, float sky, int resolution) {
  Scene s;
  const uint32_t m = s.add_material(make_diffuse(Rgb(albedo)));
  const float e = 1000.f;
  add_facing_quad(s, Vec3(-e, -e, 0), Vec3(e, -e, 0), Vec3(e, e, 0), Vec3(-e, e, 0), Vec3(0, 0, 1), m, Rgb());
  s.add_environment_light(Rgb(sky));
  s.camera = make_perspective_camera(Vec3(0, 0, 1), Vec3(0.1f, 0.2f, -1.f), Vec3(0, 1, 0), 60.f, resolution, resolution);
  s.ray_epsilon = 1e-4f;
  s.finalize();
  return s;
}

Scene make_coated_cornell_box(int resolution, bool smooth_coats, bool white_stays_diffuse) {
  Scene s = make_cornell_box(1, resolution, resolution);
  std::vector<bool> wall(s.materials.size(), false);
  for (const Triangle& t : s.triangles) {
    const Material& m = s.materials[t.material];
    const bool white = m.diffuse.r == m.diffuse.g && m.diffuse.g == m.diffuse.b;
    if (t.light == kNoLight && m.type == MaterialType::standard && !is_black(m.diffuse) && !(white_stays_diffuse && white))
      wall[t.material] = true;
  }
  int k = 0;
  for (size_t i = 0; i < s.materials.size(); ++i) {
    if (!wall[i]) continue;
    Material& m = s.materials[i];
    m.ior = 1.5f;
    m.thickness = 0.05f;
    switch (k++ % 3) {
      case 0:
        m.type = MaterialType::coated_diffuse;
        m.alpha = smooth_coats ? 0.f : 0.2f;
        break;
      case 1:
        m.type = MaterialType::coated_diffuse;
        m.alpha = 0.4f;
        m.medium_albedo = Rgb(0.6f, 0.7f, 0.8f);
        m.g = 0.3f;
        m.thickness = 0.4f;
        break;
      default:
        m.type = MaterialType::coated_conductor;
        m.alpha = smooth_coats ? 0.f : 0.15f;
        m.base_alpha = 0.3f;
        m.eta = Rgb(0.2f, 0.9f, 1.1f) * (1.f / m.ior);
        m.k = Rgb(3.9f, 2.4f, 2.2f) * (1.f / m.ior);
        break;
    }
  }
  s.finalize();
  return s;
}

}  // namespace pathspace::testing
