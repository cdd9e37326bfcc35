// Rendering helpers shared by the path space filter tests.
#pragma once

#include <cstring>

#include "pathspace/accel/accel.h"
#include "pathspace/film/film.h"
#include "pathspace/integrators/render.h"
#include "pathspace/scene/scene.h"

namespace pathspace::testing {

struct FilteredRender {
  Image mean, variance;
  RenderStats stats;
};

inline FilteredRender render_with(const Scene& scene, const IntegratorSettings& settings, uint32_t spp, int threads = 0) {
  const Accel accel(scene);
  Film film(scene.camera.width, scene.camera.height);
  RenderRequest req;
  req.spp = spp;
  req.threads = threads;
  req.settings = settings;
  FilteredRender r;
  r.stats = render(scene, accel, req, film);
  r.mean = film.mean();
  r.variance = film.variance_of_mean();
  return r;
}

inline IntegratorSettings hashed_settings(uint64_t seed = 0) {
  IntegratorSettings s;
  s.seed = seed;
  s.filter.kind = FilterKind::hashed;
  return s;
}

inline bool bit_identical(const Image& a, const Image& b) {
  if (a.width != b.width || a.height != b.height) return false;
  for (size_t i = 0; i < a.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      const float x = a.pixels[i][c], y = b.pixels[i][c];
      if (std::memcmp(&x, &y, sizeof(float)) != 0) return false;
    }
  return true;
}

}  // namespace pathspace::testing
