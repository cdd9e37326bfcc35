// Scenes made to test path space filters (Keller, Dahm, Binder 2014): a room split by a thin wall,
// for the light a filter leaks across it (the weights of sec. 2.1, fig. 4), and a fence of thin
// bars, for anti-aliasing by extra camera paths (sec. 3, fig. 7). Both are open rooms in the Cornell
// box's frame (z up, the camera looking along +y through the missing front wall).
#include "pathspace/scene/filter_scenes.h"

namespace pathspace {

namespace {

constexpr float kHalfWidth = 1.f, kHeight = 2.f;

// A quad from corner c along edges u and v; it faces cross(u, v).
void add_rect(Scene& scene, const Vec3& c, const Vec3& u, const Vec3& v, uint32_t material, const Rgb& emission = Rgb()) {
  scene.add_quad(c, c + u, c + u + v, c + v, material, emission);
}

// Floor, ceiling, back and side walls, all facing inwards; the front (y = -1) is open.
void add_open_room(Scene& scene, uint32_t walls, bool with_floor) {
  const float w = kHalfWidth, h = kHeight;
  if (with_floor) add_rect(scene, Vec3(-w, -w, 0.f), Vec3(2 * w, 0, 0), Vec3(0, 2 * w, 0), walls);
  add_rect(scene, Vec3(-w, -w, h), Vec3(0, 2 * w, 0), Vec3(2 * w, 0, 0), walls);  // ceiling
  add_rect(scene, Vec3(-w, w, 0.f), Vec3(2 * w, 0, 0), Vec3(0, 0, h), walls);     // back
  add_rect(scene, Vec3(-w, -w, 0.f), Vec3(0, 2 * w, 0), Vec3(0, 0, h), walls);    // left
  add_rect(scene, Vec3(w, -w, 0.f), Vec3(0, 0, h), Vec3(0, 2 * w, 0), walls);     // right
}

// The camera in front of the open side, the path limit and ray offset of both scenes.
Scene room_scene(int width, int height) {
  Scene scene;
  scene.camera = make_perspective_camera(Vec3(0.f, -3.4f, 1.f), Vec3(0.f, 3.4f, -0.2f), Vec3(0.f, 0.f, 1.f), 45.f, width, height);
  scene.ray_epsilon = 1e-4f;
  scene.max_path_segments = 10;
  return scene;
}

}  // namespace

Scene make_wall_leak_scene(int width, int height) {
  Scene scene = room_scene(width, height);
  const uint32_t white = scene.add_material(make_diffuse(Rgb(0.8f)));
  const uint32_t grey = scene.add_material(make_diffuse(Rgb(0.4f)));
  add_open_room(scene, white, false);
  // The lit (left) floor in stripes of two albedos, the dark (right) floor in the lighter one: the
  // albedo weight separates half of the lit floor from the dark floor, visibility all of it.
  constexpr int kStripes = 8;
  const float stripe = 2.f * kHalfWidth / kStripes;
  for (int i = 0; i < kStripes; ++i)
    add_rect(scene, Vec3(-kHalfWidth, -kHalfWidth + i * stripe, 0.f), Vec3(kHalfWidth, 0, 0), Vec3(0, stripe, 0), i % 2 ? grey : white);
  add_rect(scene, Vec3(0.f, -kHalfWidth, 0.f), Vec3(kHalfWidth, 0, 0), Vec3(0, 2 * kHalfWidth, 0), white);
  // The thin wall, floor to ceiling and front to back: nothing lit reaches the right half.
  const float t = kWallHalfThickness;
  add_rect(scene, Vec3(-t, -kHalfWidth, 0.f), Vec3(0, 0, kHeight), Vec3(0, 2 * kHalfWidth, 0), white);  // lit face (-x)
  add_rect(scene, Vec3(t, -kHalfWidth, 0.f), Vec3(0, 2 * kHalfWidth, 0), Vec3(0, 0, kHeight), white);   // dark face (+x)
  add_rect(scene, Vec3(-t, -kHalfWidth, 0.f), Vec3(2 * t, 0, 0), Vec3(0, 0, kHeight), white);          // front edge
  scene.add_point_light(Vec3(-0.1f, 0.f, 0.3f), Rgb(1.f));
  scene.finalize();
  return scene;
}

Scene make_fence_scene(int width, int height) {
  Scene scene = room_scene(width, height);
  const uint32_t white = scene.add_material(make_diffuse(Rgb(0.8f)));
  const uint32_t red = scene.add_material(make_diffuse(Rgb(0.8f, 0.15f, 0.15f)));
  const uint32_t emitter = scene.add_material(Material());
  add_open_room(scene, white, true);
  // 0.5 x 0.5 light under the ceiling, facing down.
  add_rect(scene, Vec3(-0.25f, -0.25f, kHeight - 0.01f), Vec3(0, 0.5f, 0), Vec3(0.5f, 0, 0), emitter, Rgb(12.f));
  // Bars about a pixel wide at 128 x 128, facing the camera, half-way to the back wall.
  constexpr int kBars = 13;
  for (int i = 0; i < kBars; ++i) {
    const float x = -0.9f + 1.8f * float(i) / float(kBars - 1);
    add_rect(scene, Vec3(x - 0.5f * kFenceBarWidth, 0.3f, 0.f), Vec3(kFenceBarWidth, 0, 0), Vec3(0, 0, 1.5f), red);
  }
  scene.finalize();
  return scene;
}

}  // namespace pathspace
