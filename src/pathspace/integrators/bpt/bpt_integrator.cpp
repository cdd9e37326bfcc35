// Host orchestration of bidirectional path tracing (bpt_integrator.h): buffers, pass driver, report and
// the per-strategy AOVs; the per-pixel logic (Veach 1997 ch. 10, VCM tech. report MIS) is bpt_kernel.h.
#include "pathspace/integrators/bpt/bpt_integrator.h"

#include <algorithm>

#include <fmt/format.h>

#include "pathspace/accel/accel.h"
#include "pathspace/base/error.h"
#include "pathspace/scene/scene.h"

namespace pathspace {

namespace {
double splat_scale(const BptSettings& s) { return s.splat_scale > 0.0 ? s.splat_scale : SplatFilm::kDefaultScale; }
}  // namespace

BptBuffers::BptBuffers(int width, int height, const BptSettings& settings, int max_segments)
    : splats_(width, height, splat_scale(settings)), camera_(size_t(width) * size_t(height)) {
  strategy_max_length_ = settings.strategy_images > 0 ? std::min(settings.strategy_images, max_segments) : 0;
  const int count = strategy_max_length_ > 0 ? bpt_strategy_count(strategy_max_length_) : 0;
  strategies_.reserve(size_t(count));
  for (int i = 0; i < count; ++i) {
    strategies_.emplace_back(width, height, splat_scale(settings));
    strategies_.back().clear();
  }
  for (SplatFilm& f : strategies_) strategy_views_.push_back(f.view());
}

BptFilms BptBuffers::worker_films() {
  BptFilms f;
  f.splats = splats_.worker_view();
  f.strategies = strategy_views_.empty() ? nullptr : strategy_views_.data();
  f.strategy_max_length = strategy_max_length_;
  f.light_paths = uint32_t(camera_.size());
  return f;
}

void BptBuffers::save_state(StateWriter& out) const {
  for (size_t i = 0; i < strategies_.size(); ++i) strategies_[i].save_state(out, "bpt.strategy" + std::to_string(i));
}

void BptBuffers::load_state(StateReader& in) {
  for (size_t i = 0; i < strategies_.size(); ++i) strategies_[i].load_state(in, "bpt.strategy" + std::to_string(i));
}

uint64_t BptBuffers::rejected_strategy_splats() const {
  uint64_t n = 0;
  for (const SplatFilm& f : strategies_) n += f.overflows() + f.non_finite();
  return n;
}

BptIntegrator::BptIntegrator(const Scene& scene, const Accel& accel, const BptSettings& settings, uint64_t seed)
    : view_(scene.view()), accel_(accel), settings_(settings), seed_(seed),
      max_segments_(std::min(bpt_max_segments(settings, view_), kBptMaxSegments)),
      buffers_(scene.camera.width, scene.camera.height, settings, max_segments_) {
  // An explicit limit beyond the kernel's vertex array is an error; a scene's "unlimited" one is
  // clamped (the kernel does the same), which the report states.
  if (settings.max_segments > kBptMaxSegments)
    throw Error(fmt::format("bpt supports paths of at most {} segments (asked for {})", kBptMaxSegments, settings.max_segments));
}

void BptIntegrator::render_pass(uint32_t pass, Film& film, PathCounters& counters) {
  bpt_render_pass(view_, accel_, settings_, seed_, pass, buffers_, film, counters);
  overflows_ += buffers_.splats().overflows();
  non_finite_ += buffers_.splats().non_finite();
  ++passes_;
}

void BptIntegrator::statistics(Statistics& out) const {
  out.counter("bpt.passes", passes_);
  out.counter("bpt.max_segments", uint64_t(max_segments_), "the kernel clamps an unlimited scene limit");
  out.counter("bpt.strategy_images", buffers_.strategy_max_length() > 0 ? uint64_t(bpt_strategy_count(buffers_.strategy_max_length())) : 0);
  out.counter("bpt.splat_overflows", overflows_, "t = 1 splats rejected: too large or negative");
  out.counter("bpt.splat_non_finite", non_finite_ + buffers_.rejected_strategy_splats(), "splats rejected: NaN or Inf");
}

void BptIntegrator::save_state(StateWriter& out) const {
  out.put("bpt.passes", passes_);
  out.put("bpt.overflows", overflows_);
  out.put("bpt.non_finite", non_finite_);
  buffers_.save_state(out);
}

void BptIntegrator::load_state(StateReader& in) {
  in.get("bpt.passes", &passes_);
  in.get("bpt.overflows", &overflows_);
  in.get("bpt.non_finite", &non_finite_);
  buffers_.load_state(in);
}

std::vector<NamedImage> BptIntegrator::aovs() const {
  std::vector<NamedImage> out;
  const int w = view_.camera.width, h = view_.camera.height;
  const float inv = passes_ > 0 ? 1.f / float(passes_) : 0.f;
  for (int k = 1; k <= buffers_.strategy_max_length(); ++k)
    for (int s = 0; s <= k; ++s) {
      const int t = k + 1 - s;
      Image img(w, h);
      for (size_t i = 0; i < img.size(); ++i) img.pixels[i] = buffers_.strategy_sum(s, t, uint32_t(i)) * inv;
      out.push_back({fmt::format("bpt-s{}-t{}", s, t), std::move(img)});
    }
  return out;
}

}  // namespace pathspace
