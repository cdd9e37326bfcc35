#include "support/media_scenes.h"

#include "pathspace/scene/builtin_scenes.h"
#include "pathspace/scene/media_scenes.h"

namespace pathspace::testing {

namespace {

// The grid of the fog box: 6 x 5 x 4 samples over the box's interior, denser towards the floor and
// chromatic (three channels), with an albedo grid of its own.
GridMediumDesc fog_grid(const Bounds3& box) {
  GridMediumDesc d;
  d.nx = 6;
  d.ny = 5;
  d.nz = 4;
  d.channels = 3;
  for (uint32_t z = 0; z < d.nz; ++z)
    for (uint32_t y = 0; y < d.ny; ++y)
      for (uint32_t x = 0; x < d.nx; ++x) {
        const float base = 0.2f + 0.5f * float((x + 2 * y + 3 * z) % 4);
        d.density.insert(d.density.end(), {base, 0.5f * base + 0.1f, 1.2f * base});
      }
  d.sigma_t_scale = Rgb(1.f);
  d.albedo_nx = 2;
  d.albedo_ny = 2;
  d.albedo_nz = 2;
  for (int i = 0; i < 8; ++i) d.albedo_values.insert(d.albedo_values.end(), {0.9f, 0.6f + 0.04f * float(i), 0.8f});
  const Vec3 size = box.hi - box.lo;
  const float m[12] = {1.f / size.x, 0.f, 0.f, -box.lo.x / size.x, 0.f, 1.f / size.y, 0.f, -box.lo.y / size.y,
                       0.f, 0.f, 1.f / size.z, -box.lo.z / size.z};
  std::copy(std::begin(m), std::end(m), d.world_to_grid);
  return d;
}

void fill_world(Scene* s, uint32_t medium) {
  s->media.camera_medium = int32_t(medium);
  for (uint32_t i = 0; i < s->lights.size(); ++i) s->media.bind_light(i, int32_t(medium));
}

Scene box_with_sphere(int width, int height, const Material& boundary, uint32_t medium) {
  Scene s = make_cornell_box(kLightCeiling, width, height);
  const Bounds3 b = s.geometry_bounds();
  const Vec3 c = (b.lo + b.hi) * 0.5f;
  const float r = 0.22f * (b.hi.x - b.lo.x);
  const uint32_t mat = s.add_material(boundary);
  const uint32_t sphere = s.add_sphere(Vec3(c.x, b.lo.y + r * 1.05f, c.z), r, mat);
  s.media.bind_sphere(sphere, make_medium_interface(int32_t(medium), kVacuum));
  return s;
}

}  // namespace

Scene make_fog_cornell_box(int width, int height, bool grid) {
  if (!grid) return make_fog_box_scene(width, height);  // the built-in cornell-fog
  Scene s = make_cornell_box(kLightCeiling, width, height);
  const Bounds3 b = s.geometry_bounds();
  const float size = b.hi.x - b.lo.x;
  // As cornell-fog, the grid filling the box just outside its walls.
  const Vec3 margin = (b.hi - b.lo) * 0.002f;
  const Bounds3 inside{b.lo - margin, b.hi + margin};
  const uint32_t m = s.media.add_grid(fog_grid(inside));
  s.media.media[m].sigma_t = Rgb(1.f / size);
  add_medium_box(&s, inside, m);
  for (uint32_t i = 0; i < s.lights.size(); ++i) s.media.bind_light(i, int32_t(m));
  s.finalize();
  return s;
}

namespace {
// The Cornell box with a sphere of `boundary` around a homogeneous medium of the given coefficients
// (per box size).
Scene box_with_medium_sphere(int width, int height, const Material& boundary, const Rgb& sigma_a, const Rgb& sigma_s, float g) {
  Scene probe = make_cornell_box(kLightCeiling, 4, 4);
  const float size = probe.geometry_bounds().hi.x - probe.geometry_bounds().lo.x;
  SceneMedia media;
  const uint32_t m = media.add_homogeneous(sigma_a / size, sigma_s / size, g);
  Scene s = box_with_sphere(width, height, boundary, m);
  s.media.media = media.media;
  s.finalize();
  return s;
}
}  // namespace

Scene make_smoke_sphere_box(int width, int height) {
  Material boundary;
  boundary.type = MaterialType::interface;
  return box_with_medium_sphere(width, height, boundary, Rgb(0.5f, 1.f, 1.5f), Rgb(8.f, 6.f, 4.f), -0.3f);
}

Scene make_translucent_sphere_box(int width, int height) {
  return box_with_medium_sphere(width, height, make_rough_dielectric(0.8f, 1.33f), Rgb(0.2f, 0.5f, 1.f), Rgb(20.f, 16.f, 12.f),
                                0.5f);
}

Scene make_medium_furnace(int resolution, bool glass_boundary, float sky) {
  Scene s;
  s.name = glass_boundary ? "medium-furnace-glass" : "medium-furnace";
  Material boundary;
  if (glass_boundary) {
    boundary = make_glass(1.5f);
  } else {
    boundary.type = MaterialType::interface;
  }
  const uint32_t mat = s.add_material(boundary);
  const uint32_t sphere = s.add_sphere(Vec3(0.f), 1.f, mat);
  const uint32_t m = s.media.add_homogeneous(Rgb(0.f), Rgb(2.f, 0.7f, 4.f), 0.6f);  // albedo 1, chromatic
  s.media.bind_sphere(sphere, make_medium_interface(int32_t(m), kVacuum));
  s.add_environment_light(Rgb(sky));
  s.camera = make_perspective_camera(Vec3(0.f, 0.f, 4.f), Vec3(0.f, 0.f, -1.f), Vec3(0.f, 1.f, 0.f), 40.f, resolution, resolution);
  s.max_path_segments = 1000;
  s.finalize();
  return s;
}

Scene make_absorbing_slab(int resolution, const Rgb& sigma_a, float le) {
  Scene s;
  s.name = "absorbing-slab";
  const uint32_t black = s.add_material(make_diffuse(Rgb(0.f)));
  s.add_quad(Vec3(-4.f, -4.f, -3.f), Vec3(4.f, -4.f, -3.f), Vec3(4.f, 4.f, -3.f), Vec3(-4.f, 4.f, -3.f), black, Rgb(le));
  const uint32_t m = s.media.add_homogeneous(sigma_a, Rgb(0.f), 0.f);
  add_medium_box(&s, Bounds3{Vec3(-20.f, -20.f, -1.f), Vec3(20.f, 20.f, 0.f)}, m);
  s.camera = make_perspective_camera(Vec3(0.f, 0.f, 2.f), Vec3(0.f, 0.f, -1.f), Vec3(0.f, 1.f, 0.f), 70.f, resolution, resolution);
  s.finalize();
  return s;
}

Scene make_single_scattering_scene(int resolution, const SingleScattering& p) {
  Scene s;
  s.name = "single-scattering";
  // One small triangle far behind the camera, so the scene has geometry; no path reaches it.
  const uint32_t mat = s.add_material(make_diffuse(Rgb(0.f)));
  s.add_triangle(Vec3(0.f, 0.f, -1000.f), Vec3(0.01f, 0.f, -1000.f), Vec3(0.f, 0.01f, -1000.f), mat);
  s.add_point_light(p.light, p.intensity);
  const uint32_t m = s.media.add_homogeneous(p.sigma_a, p.sigma_s, p.g);
  fill_world(&s, m);
  s.camera = make_perspective_camera(Vec3(0.f), Vec3(0.f, 0.f, 1.f), Vec3(0.f, 1.f, 0.f), 60.f, resolution, resolution);
  s.max_path_segments = 2;
  s.finalize();
  return s;
}

}  // namespace pathspace::testing
