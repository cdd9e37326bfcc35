// Rendering helpers shared by the path space filter tests.
#pragma once

#include <cstring>

#include "pathspace/accel/accel.h"
#include "pathspace/filters/hashed_filter_settings.h"
#include "pathspace/integrators/pt/pt_settings.h"
#include "pathspace/scene/scene.h"
#include "pathspace/session/render.h"

namespace pathspace::testing {

struct FilteredRender {
  Image mean, variance;
  RenderStats stats;
};

// Renders `spp` passes of `config` with `threads` threads (<= 0: all cores).
inline FilteredRender render_with(const Scene& scene, RenderConfig config, uint32_t spp, int threads = 0) {
  const Accel accel(scene);
  config.threads = threads;
  RenderSnapshot snap = render(scene, accel, config, RunLimit::for_passes(spp));
  return {std::move(snap.mean), std::move(snap.variance), std::move(snap.stats)};
}

// Path tracing with the hashed filter.
inline RenderConfig hashed_config(uint64_t seed = 0, const HashedFilterSettings& filter = {}, const PtSettings& pt = {}) {
  return with_filter(make_render_config("pt", pt, seed), "hashed", filter);
}

// Plain path tracing.
inline RenderConfig pt_config(uint64_t seed = 0, const PtSettings& pt = {}) { return make_render_config("pt", pt, seed); }

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
