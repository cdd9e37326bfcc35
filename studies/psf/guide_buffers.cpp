#include "studies/psf/guide_buffers.h"

#include <algorithm>
#include <cmath>

#include "pathspace/accel/accel.h"
#include "pathspace/parallel/parallel_for.h"
#include "pathspace/scene/scene.h"
#include "pathspace/scene/shading_material.h"

namespace pathspace::study {

namespace {

void resize(GuideBuffers* g, int width, int height) {
  const size_t n = size_t(width) * size_t(height);
  g->width = width;
  g->height = height;
  g->hit.assign(n, 0);
  g->normal.assign(n, Vec3{});
  g->albedo.assign(n, Rgb{});
  g->position.assign(n, Vec3{});
  g->footprint.assign(n, 0.f);
}

}  // namespace

GuideBuffers GuideBuffers::uniform(int width, int height, Vec3 normal, Rgb albedo) {
  GuideBuffers g;
  resize(&g, width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const size_t i = size_t(y) * size_t(width) + size_t(x);
      g.hit[i] = 1;
      g.normal[i] = normal;
      g.albedo[i] = albedo;
      g.position[i] = Vec3{float(x), float(y), 0.f};
      g.footprint[i] = 1.f;
    }
  return g;
}

GuideBuffers render_guide_buffers(const Scene& scene, const Accel& accel) {
  const PerspectiveCamera& camera = scene.camera;
  GuideBuffers g;
  resize(&g, camera.width, camera.height);
  const SceneView view = scene.view();
  parallel_for(size_t(camera.height), 1, [&](size_t row_begin, size_t row_end) {
    for (size_t row = row_begin; row < row_end; ++row) {
      for (int x = 0; x < camera.width; ++x) {
        const int y = int(row);
        const size_t i = size_t(y) * size_t(camera.width) + size_t(x);
        const Ray ray = camera.generate_ray(float(x) + 0.5f, float(y) + 0.5f);
        SurfaceHit hit;
        if (!accel.intersect(ray, &hit)) continue;
        const Material m = shading_material(view, hit);
        // The angle between neighbouring pixel centres' rays, times the distance: one pixel's width there.
        const Ray next = camera.generate_ray(float(x) + 1.5f, float(y) + 0.5f);
        const float angle = std::acos(std::clamp(dot(ray.d, next.d), -1.f, 1.f));
        g.hit[i] = 1;
        g.normal[i] = face_forward(hit.ns, -ray.d);
        g.albedo[i] = m.diffuse + m.glossy + m.specular;
        g.position[i] = hit.p;
        g.footprint[i] = std::max(hit.t * angle, 1e-6f);
      }
    }
  });
  return g;
}

}  // namespace pathspace::study
