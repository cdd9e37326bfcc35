// The state `pathspace view` shares between its render loop and its server (viewer_server.h): the
// camera the page asks for, the display exposure, and the newest encoded frame.
#pragma once

#include <condition_variable>
#include <mutex>
#include <optional>

#include "pathspace/film/image.h"
#include "pathspace/session/render_session.h"
#include "viewer/viewer_server.h"

namespace pathspace::viewer {

class LiveView final : public ViewerBackend {
 public:
  // `home`: the scene's camera (Reset); `step`: scene units of one move step; `session`: cancelled
  // when the camera changes, so that the pass in flight ends and the loop restarts the view.
  LiveView(const PerspectiveCamera& home, float step, RenderSession* session);

  std::optional<Frame> next_frame(uint64_t after, std::chrono::milliseconds wait) override;
  void apply(const Command& command) override;

  // For the render loop: the camera to render when it changed since the last call.
  std::optional<PerspectiveCamera> take_camera();
  // Encodes the film's mean (display exposure applied) as the next frame.
  void publish(const Image& mean, const RenderStats& stats, uint64_t view);
  // Waits until the camera or the exposure changes, or `wait` passes (an idle loop); true when the
  // exposure changed (the frame is to be shown again).
  bool wait_for_change(std::chrono::milliseconds wait);

 private:
  const PerspectiveCamera home_;
  const float step_;
  RenderSession* session_;
  std::mutex mutex_;
  std::condition_variable frame_ready_, changed_;
  PerspectiveCamera camera_;
  bool camera_changed_ = false;
  double exposure_stops_ = 0.0;
  bool exposure_changed_ = false;
  Frame frame_;
  std::chrono::steady_clock::time_point view_start_ = std::chrono::steady_clock::now();
};

}  // namespace pathspace::viewer
