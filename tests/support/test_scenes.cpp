#include "support/test_scenes.h"

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

}  // namespace pathspace::testing
