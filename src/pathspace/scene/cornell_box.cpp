// SmallVCM's Cornell box variants with every number and convention of docs/scenes.md:
// geometry §3, materials §4, lights §5, camera §2, 10-segment path limit and 1e-3 ray offsets §6.
#include "pathspace/base/error.h"
#include "pathspace/scene/builtin_scenes.h"
#include "pathspace/scene/animated_scenes.h"
#include "pathspace/scene/filter_scenes.h"
#include "pathspace/scene/media_scenes.h"

namespace pathspace {

const std::vector<BuiltinSceneInfo>& builtin_scenes() {
  static const std::vector<BuiltinSceneInfo> scenes = {
      {"cornell-empty-area", "e_c", 1, "all-diffuse empty Cornell box, area light"},
      {"cornell-empty-point", "e_p", 4, "all-diffuse empty Cornell box, point light"},
      {"cornell-box", "bs_c", 193, "diffuse box, small mirror and glass spheres, area light (default)"},
      {"cornell-glossy", "gbs_c", 449, "glossy floor, blue back wall, small mirror and glass spheres, area light"},
      {"cornell-glossy-large-mirror", "glm_c", 273, "glossy floor, blue back wall, large mirror sphere, area light"},
      {"cornell-glossy-point", "gbs_p", 452, "glossy floor, blue back wall, small spheres, point light"},
      {"cornell-glossy-background", "gbs_b", 456, "glossy floor, blue back wall, small spheres, constant background light"},
      {"cornell-glossy-sun", "gbs_s", 450, "glossy floor, blue back wall, small spheres, directional sun"},
      {"filter-leak", "f_l", 0, "room split by a thin wall, point light on one side (light a filter leaks)", make_wall_leak_scene},
      {"filter-fence", "f_f", 0, "room with a fence of pixel-thin bars, ceiling light (anti-aliasing)", make_fence_scene},
      {"cornell-fog", "fog_c", 0, "empty Cornell box filled with chromatic fog, area light (participating media)", make_fog_box_scene},
      {"cornell-moving-light", "ml_c", 0, "animated: Cornell box with a diffuse sphere, its ceiling light sweeping left and right (2021 paper fig. 9)",
       make_moving_light_frame0, make_moving_light_scene},
      {"cornell-moving-sphere", "ms_c", 0, "animated: Cornell box with a diffuse sphere circling on the floor", make_moving_sphere_frame0,
       make_moving_sphere_scene},
  };
  return scenes;
}

const BuiltinSceneInfo* find_builtin_scene(const std::string& name_or_id) {
  for (const BuiltinSceneInfo& s : builtin_scenes())
    if (s.name == name_or_id || s.id == name_or_id) return &s;
  return nullptr;
}

Scene make_builtin_scene(const std::string& name_or_id, int width, int height) {
  const BuiltinSceneInfo* info = find_builtin_scene(name_or_id);
  if (!info) throw Error("unknown scene '" + name_or_id + "' (see 'pathspace info --scenes')");
  Scene scene = info->build ? info->build(width, height) : make_cornell_box(info->mask, width, height);
  scene.name = info->name;
  return scene;
}

Scene make_builtin_scene_at(const std::string& name_or_id, int width, int height, double seconds) {
  const BuiltinSceneInfo* info = find_builtin_scene(name_or_id);
  if (!info || !info->animate) return make_builtin_scene(name_or_id, width, height);
  Scene scene = info->animate(width, height, seconds);
  scene.name = info->name;
  return scene;
}

Scene make_cornell_box(unsigned mask, int width, int height, const Vec3& light_offset) {
  Scene scene;
  // §2: camera. SmallVCM uses the same tan for x and y (square_pixels = false).
  scene.camera = make_perspective_camera(Vec3(-0.0439815f, -4.12529f, 0.222539f), Vec3(0.00688625f, 0.998505f, -0.0542161f),
                                     Vec3(3.73896e-4f, 0.0542148f, 0.998529f), 45.f, width, height, false);
  scene.ray_epsilon = 1e-3f;     // §6 (applied along the normal, see geometry/ray.h)
  scene.max_path_segments = 10;  // §6

  // §4: materials (ids as in the table; 0 and 1 are the black emitters).
  const Rgb white(0.803922f), green(0.156863f, 0.803922f, 0.172549f), red(0.803922f, 0.152941f, 0.152941f),
      blue(0.156863f, 0.172549f, 0.803922f);
  const uint32_t emitter = scene.add_material(Material());
  scene.add_material(Material());
  const uint32_t glossy = scene.add_material(make_phong(Rgb(0.1f), Rgb(0.7f), 90.f));
  const uint32_t green_m = scene.add_material(make_diffuse(green));
  const uint32_t red_m = scene.add_material(make_diffuse(red));
  const uint32_t white_m = scene.add_material(make_diffuse(white));
  const uint32_t mirror = scene.add_material(make_mirror(Rgb(1.f)));
  const uint32_t glass = scene.add_material(make_glass(1.6f, Rgb(1.f)));
  const uint32_t blue_m = scene.add_material(make_diffuse(blue));

  // §3.1–3.2: the box, open at the front; vertex order fixes the (inward) normals.
  const Vec3 cb[8] = {{-1.27029f, 1.30455f, -1.28002f}, {1.28975f, 1.30455f, -1.28002f},
                      {1.28975f, 1.30455f, 1.28002f},   {-1.27029f, 1.30455f, 1.28002f},
                      {-1.27029f, -1.25549f, -1.28002f}, {1.28975f, -1.25549f, -1.28002f},
                      {1.28975f, -1.25549f, 1.28002f},   {-1.27029f, -1.25549f, 1.28002f}};
  const bool glossy_floor = mask & kGlossyFloor;
  const uint32_t floor_m = glossy_floor ? glossy : white_m;
  const uint32_t back_m = glossy_floor ? blue_m : white_m;
  scene.add_triangle(cb[0], cb[4], cb[5], floor_m);
  scene.add_triangle(cb[5], cb[1], cb[0], floor_m);
  scene.add_triangle(cb[0], cb[1], cb[2], back_m);
  scene.add_triangle(cb[2], cb[3], cb[0], back_m);
  scene.add_triangle(cb[2], cb[6], cb[7], white_m);
  scene.add_triangle(cb[7], cb[3], cb[2], white_m);
  scene.add_triangle(cb[3], cb[7], cb[4], green_m);
  scene.add_triangle(cb[4], cb[0], cb[3], green_m);
  scene.add_triangle(cb[1], cb[5], cb[6], red_m);
  scene.add_triangle(cb[6], cb[2], cb[1], red_m);

  // §3.3: spheres (mirror wins over glass for the large one).
  const float floor_z = -1.28002f, mid_y = 0.02453005f;
  if (mask & kLargeMirrorSphere)
    scene.add_sphere(Vec3(0.00972998f, mid_y, floor_z + 0.8f), 0.8f, mirror);
  else if (mask & kLargeGlassSphere)
    scene.add_sphere(Vec3(0.00972998f, mid_y, floor_z + 0.8f), 0.8f, glass);
  if (mask & kSmallMirrorSphere) scene.add_sphere(Vec3(-1.27029f + (2.f / 7.f) * 2.56004f, mid_y, floor_z + 0.5f), 0.5f, mirror);
  if (mask & kSmallGlassSphere) scene.add_sphere(Vec3(1.28975f - (2.f / 7.f) * 2.56004f, mid_y, floor_z + 0.5f), 0.5f, glass);

  // §3.4: the light box, absent in point-light scenes; its bottom emits only with kLightCeiling.
  if (!(mask & kLightPoint)) {
    Vec3 lb[8] = {{-0.25f, 0.25f, 1.26002f}, {0.25f, 0.25f, 1.26002f},   {0.25f, 0.25f, 1.28002f},
                  {-0.25f, 0.25f, 1.28002f}, {-0.25f, -0.25f, 1.26002f}, {0.25f, -0.25f, 1.26002f},
                  {0.25f, -0.25f, 1.28002f}, {-0.25f, -0.25f, 1.28002f}};
    for (Vec3& p : lb) p = p + light_offset;  // animated scenes move it (animated_scenes.h)
    scene.add_triangle(lb[0], lb[2], lb[1], white_m);
    scene.add_triangle(lb[2], lb[0], lb[3], white_m);
    scene.add_triangle(lb[3], lb[4], lb[7], white_m);
    scene.add_triangle(lb[4], lb[3], lb[0], white_m);
    scene.add_triangle(lb[1], lb[6], lb[5], white_m);
    scene.add_triangle(lb[6], lb[1], lb[2], white_m);
    scene.add_triangle(lb[4], lb[5], lb[6], white_m);
    scene.add_triangle(lb[6], lb[7], lb[4], white_m);
    const bool emits = mask & kLightCeiling;
    const Rgb le = emits ? Rgb(25.03329895614464f) : Rgb();  // §5: radiance of the 0.5 x 0.5 emitter
    scene.add_triangle(lb[0], lb[5], lb[4], emits ? emitter : white_m, le);
    scene.add_triangle(lb[5], lb[0], lb[1], emits ? emitter + 1 : white_m, le);
  }

  // §5: the other lights.
  if (mask & kLightPoint) scene.add_point_light(Vec3(0.f, -0.5f, 1.f), Rgb(70.f / (4.f * kPi)));
  if (mask & kLightSun) scene.add_directional_light(Vec3(-1.f, 1.5f, -1.f), Rgb(10.f, 4.f, 0.f));
  if (mask & kLightBackground) scene.add_environment_light(Rgb(135.f / 255.f, 206.f / 255.f, 250.f / 255.f));

  scene.has_bounds_override = true;  // §5: half the diagonal of the box
  scene.bounds_override = {Vec3(0.00972998f, 0.02453005f, 0.f), 2.21705961f};
  scene.light_selection = LightSelection::uniform;  // §5: uniform over lights (noise only)
  scene.finalize();
  return scene;
}

}  // namespace pathspace
