#include "pathspace/scene/media_scenes.h"

#include "pathspace/scene/builtin_scenes.h"

namespace pathspace {

void add_medium_box(Scene* s, const Bounds3& box, uint32_t medium) {
  Material boundary;
  boundary.type = MaterialType::interface;
  const uint32_t mat = s->add_material(boundary);
  const Vec3 a = box.lo, b = box.hi;
  const Vec3 c[8] = {{a.x, a.y, a.z}, {b.x, a.y, a.z}, {b.x, b.y, a.z}, {a.x, b.y, a.z},
                     {a.x, a.y, b.z}, {b.x, a.y, b.z}, {b.x, b.y, b.z}, {a.x, b.y, b.z}};
  const int faces[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {2, 3, 7, 6}, {1, 2, 6, 5}, {0, 4, 7, 3}};
  for (const auto& f : faces) {
    const uint32_t first = uint32_t(s->triangles.size());
    s->add_quad(c[f[0]], c[f[1]], c[f[2]], c[f[3]], mat);
    for (uint32_t t = first; t < s->triangles.size(); ++t) s->media.bind_triangle(t, make_medium_interface(int32_t(medium), kVacuum));
  }
}

Scene make_fog_box_scene(int width, int height) {
  Scene s = make_cornell_box(kLightCeiling, width, height);
  const Bounds3 b = s.geometry_bounds();
  const float size = b.hi.x - b.lo.x;
  const Vec3 margin = (b.hi - b.lo) * 0.002f;
  const uint32_t m = s.media.add_homogeneous(Rgb(0.15f, 0.1f, 0.2f) / size, Rgb(0.6f, 0.8f, 0.7f) / size, 0.3f);
  add_medium_box(&s, Bounds3{b.lo - margin, b.hi + margin}, m);
  for (uint32_t i = 0; i < s.lights.size(); ++i) s.media.bind_light(i, int32_t(m));
  s.finalize();
  return s;
}

}  // namespace pathspace
