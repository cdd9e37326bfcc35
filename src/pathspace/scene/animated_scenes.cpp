#include "pathspace/scene/animated_scenes.h"

#include <cmath>

#include "pathspace/scene/builtin_scenes.h"

namespace pathspace {

namespace {
double phase(double seconds) { return 2.0 * double(kPi) * seconds / kMovingScenePeriod; }
}  // namespace

Scene make_moving_light_scene(int width, int height, double seconds) {
  // From the left wall's side to the right and back: fastest at 1 s (frame 30 at 30 frames per
  // second), where fig. 9's shadow boundary is measured.
  const float x = -kMovingLightAmplitude * float(std::cos(phase(seconds)));
  Scene scene = make_cornell_box(kLightCeiling, width, height, Vec3(x, 0.f, 0.f));
  scene.first_moving_triangle = uint32_t(scene.triangles.size()) - kLightBoxTriangles;  // the light box comes last
  // A diffuse sphere standing still on the floor: its shadow moves with the light (fig. 9).
  scene.add_sphere(Vec3(0.00972998f, 0.02453005f, -1.28002f + 0.5f), 0.5f, scene.add_material(make_diffuse(Rgb(0.75f, 0.7f, 0.6f))));
  scene.finalize();
  return scene;
}

Scene make_moving_light_frame0(int width, int height) { return make_moving_light_scene(width, height, 0.0); }

Scene make_moving_sphere_scene(int width, int height, double seconds) {
  Scene scene = make_cornell_box(kLightCeiling, width, height);
  const float radius = 0.4f, floor_z = -1.28002f, orbit = 0.6f;
  const double a = phase(seconds);
  const Vec3 centre(0.00972998f + orbit * float(std::cos(a)), 0.02453005f + orbit * float(std::sin(a)), floor_z + radius);
  scene.first_moving_sphere = uint32_t(scene.spheres.size());
  scene.add_sphere(centre, radius, scene.add_material(make_diffuse(Rgb(0.75f, 0.7f, 0.6f))));
  scene.finalize();
  return scene;
}

Scene make_moving_sphere_frame0(int width, int height) { return make_moving_sphere_scene(width, height, 0.0); }

}  // namespace pathspace
