// Rendering helpers shared by the path space filter tests.
#pragma once

#include <cmath>
#include <cstring>
#include <functional>
#include <vector>

#include <gtest/gtest.h>

#include "pathspace/accel/accel.h"
#include "pathspace/filters/hashed/hashed_filter_settings.h"
#include "pathspace/integrators/pt/pt_settings.h"
#include "pathspace/scene/scene.h"
#include "pathspace/session/frame_sequence.h"
#include "pathspace/session/render.h"
#include "support/statistics.h"

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

// Furnace check: the red channel's image mean over `passes` independent single-pass renders
// (config_for_pass(p) gives each its own seed) equals `expected` by a t-test at level alpha.
inline void expect_exact_image_mean(const Scene& scene, const std::function<RenderConfig(int)>& config_for_pass, int passes,
                                    double expected, double alpha, const std::string& what) {
  double sum = 0, sum_sq = 0;
  for (int p = 0; p < passes; ++p) {
    const FilteredRender r = render_with(scene, config_for_pass(p), 1);
    double m = 0;
    for (const Rgb& px : r.mean.pixels) m += px.r;
    m /= double(r.mean.size());
    sum += m;
    sum_sq += m * m;
  }
  const MeanTest t = t_test_mean(sum, sum_sq, passes, expected);
  EXPECT_GT(t.p, alpha) << what << ": mean " << t.mean << " +- " << t.std_error << ", expected " << expected;
}

// An animation whose every frame is `scene` (a copy).
inline Animation still(const Scene& scene) {
  Animation a;
  a.scene_at = [scene](double) { return scene; };
  return a;
}

// The images of frames 0 .. frames - 1 of `animation`, one pass each, with `threads` threads; the
// last frame's statistics into *last_stats.
inline std::vector<Image> frames_of(const Animation& animation, const RenderConfig& config, uint64_t frames, int threads = 0,
                                    Statistics* last_stats = nullptr) {
  RenderConfig c = config;
  c.threads = threads;
  std::vector<Image> images;
  render_frames(animation, c, FrameRange{0, frames - 1}, 1, [&](const FrameResult& f) {
    images.push_back(f.snapshot.mean);
    if (last_stats) *last_stats = f.snapshot.stats.details;
    return true;
  });
  return images;
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

// The largest per-pixel, per-channel difference relative to max(|b|, floor).
inline double largest_relative_difference(const Image& a, const Image& b, double floor = 1e-6) {
  if (a.width != b.width || a.height != b.height) return INFINITY;
  double largest = 0.0;
  for (size_t i = 0; i < a.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      const double x = a.pixels[i][c], y = b.pixels[i][c];
      largest = std::fmax(largest, std::fabs(x - y) / std::fmax(floor, std::fabs(y)));
    }
  return largest;
}

}  // namespace pathspace::testing
