#include "viewer/live_view.h"

#include <cmath>

#include <nlohmann/json.hpp>

#include "pathspace/io/image_io.h"
#include "viewer/camera_controls.h"

namespace pathspace::viewer {

LiveView::LiveView(const PerspectiveCamera& home, float step, RenderSession* session)
    : home_(home), step_(step), session_(session), camera_(home) {}

std::optional<Frame> LiveView::next_frame(uint64_t after, std::chrono::milliseconds wait) {
  std::unique_lock<std::mutex> lock(mutex_);
  if (!frame_ready_.wait_for(lock, wait, [&] { return frame_.sequence > after; })) return std::nullopt;
  return frame_;
}

void LiveView::apply(const Command& command) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (const auto* m = std::get_if<Move>(&command)) {
      move_camera(&camera_, m->right, m->up, m->forward, step_);
      camera_changed_ = true;
    } else if (const auto* t = std::get_if<Turn>(&command)) {
      turn_camera(&camera_, t->yaw, t->pitch);
      camera_changed_ = true;
    } else if (std::holds_alternative<Reset>(command)) {
      camera_ = home_;
      camera_changed_ = true;
    } else if (const auto* e = std::get_if<Exposure>(&command)) {
      exposure_stops_ = e->stops;
      exposure_changed_ = true;
    }
  }
  changed_.notify_all();
  if (std::holds_alternative<Move>(command) || std::holds_alternative<Turn>(command) || std::holds_alternative<Reset>(command))
    session_->cancel();  // the pass in flight shows the old view: end it now
}

std::optional<PerspectiveCamera> LiveView::take_camera() {
  std::lock_guard<std::mutex> lock(mutex_);
  if (!camera_changed_) return std::nullopt;
  camera_changed_ = false;
  view_start_ = std::chrono::steady_clock::now();
  return camera_;
}

void LiveView::publish(const Image& mean, const RenderStats& stats, uint64_t view) {
  double stops;
  std::chrono::steady_clock::time_point start;
  PerspectiveCamera camera;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    camera = camera_;
    stops = exposure_stops_;
    exposure_changed_ = false;
    start = view_start_;
  }
  Image shown = mean;
  const float scale = float(std::exp2(stops));
  if (scale != 1.f)
    for (Rgb& p : shown.pixels) p = p * scale;
  auto png = std::make_shared<const std::string>(encode_image("frame.png", shown, ImageEncoding::fast));
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const nlohmann::json j = {{"stats",
                             {{"width", mean.width},
                              {"height", mean.height},
                              {"spp", stats.spp},
                              {"view", view},
                              {"passes_per_second", seconds > 0.0 ? double(stats.spp) / seconds : 0.0},
                              {"camera_options", camera_options(camera)}}}};
  {
    std::lock_guard<std::mutex> lock(mutex_);
    frame_.sequence += 1;
    frame_.png = std::move(png);
    frame_.stats_json = j.dump();
  }
  frame_ready_.notify_all();
}

bool LiveView::wait_for_change(std::chrono::milliseconds wait) {
  std::unique_lock<std::mutex> lock(mutex_);
  changed_.wait_for(lock, wait, [&] { return camera_changed_ || exposure_changed_; });
  return exposure_changed_;
}

}  // namespace pathspace::viewer
