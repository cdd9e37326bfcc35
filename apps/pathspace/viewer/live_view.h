// The state `pathspace view` shares between its render loop and its server (viewer_server.h): the
// camera and the integrator, filter and options the page asks for, the display exposure, and the
// newest encoded frame.
#pragma once

#include <condition_variable>
#include <functional>
#include <mutex>
#include <optional>
#include <vector>

#include "pathspace/film/image.h"
#include "pathspace/options/option_values.h"
#include "pathspace/session/render_config.h"
#include "pathspace/session/render_session.h"
#include "viewer/display.h"
#include "viewer/viewer_server.h"

namespace pathspace::viewer {

// What chooses the render besides the scene: the integrator, the filter and the options given by
// name (as on the command line), with the seed, threads and device they run with.
struct RenderChoice {
  std::string integrator, filter;
  OptionValues given;
  uint64_t seed = 0;
  int threads = 0;
  std::string device;
};

// Writes a saved frame (Save): the image as rendered, how the page shows it, and a label naming the
// view ("view3-64spp", with the debug image's name when one is shown); returns the reply to the client.
using FrameSaver = std::function<std::string(const Image& image, const Display& display, const std::string& label)>;

// Records a flight (Record): start() and stop() return the replies to the client (stop() may take
// seconds: it encodes the video); frame() writes one frame shown, on the render thread.
struct FlightRecorder {
  std::function<std::string()> start;
  std::function<void(const Image& image, const Display& display)> frame;
  std::function<std::string()> stop;
};

class LiveView final : public ViewerBackend {
 public:
  // `home`: the scene's camera (Reset); `step`: scene units of one move step; `choice`: what the
  // session was configured from.
  // `reference`: an image of the scene's size to measure the render against (relMSE, block relMSE,
  // blotched blocks, FLIP; the "error" image), or null.
  // `animation_fps`: frames per second of the scene's animation time, 0 for a scene that does not
  // move (no Play or Seek then).
  LiveView(const PerspectiveCamera& home, float step, RenderChoice choice, FrameSaver saver, std::shared_ptr<const Image> reference,
           FlightRecorder recorder, double animation_fps = 0.0);

  std::optional<Frame> next_frame(uint64_t after, std::chrono::milliseconds wait) override;
  std::optional<std::string> apply(const Command& command) override;

  // For the render loop: the sessions now running (the view, and the split screen's right half when
  // on). A change of the camera or the options aborts them (RenderSession::abort), so that the pass
  // in flight stops at once and the loop restarts the view; the pixel inspector reads them. Call it
  // before a session in the list is destroyed.
  void set_sessions(std::vector<RenderSession*> sessions);
  // The camera to render when it changed since the last call.
  std::optional<PerspectiveCamera> take_camera();
  // The page's camera now.
  PerspectiveCamera camera() const;
  // The animation's time in seconds when it changed since the last call (Seek, or a frame played).
  std::optional<double> take_time();
  // While playing: the next frame of the animation (the render loop calls it when a frame is done).
  void advance_if_playing();
  // The configuration to render with when the options changed since the last call.
  std::optional<RenderConfig> take_config();
  // After take_config: the render loop made the session (config_applied), or making it failed
  // (an error only a session finds, e.g. --device cuda without a GPU): the options go back to the
  // last applied ones and the next frame carries the message.
  void config_applied();
  void config_failed(const std::string& message);
  // Making the split screen's session failed: the split is off, the next frame carries the message.
  void split_failed(const std::string& message);
  // The split screen's right-half configuration when it changed since the last call: a config, or
  // nullopt inside for "off".
  std::optional<std::optional<RenderConfig>> take_split();
  // Makes the snapshot's mean the left half and `right`'s the right half of the shown image.
  static void compose_split(RenderSnapshot* left, const RenderSnapshot& right);
  // Scales a preview's images (mean and debug images) up to width x height, each pixel repeated.
  static void scale_up(RenderSnapshot* preview, int width, int height);
  // Makes the shown image of the snapshot (the film's mean, or a debug image) the next frame. It is
  // encoded (display exposure applied) by the first client that asks for it, on its own thread,
  // so that the render thread only copies it. `preview` > 1: the snapshot is a preview rendered at
  // 1/preview of the resolution and scaled up (no metrics against the reference).
  void publish(RenderSnapshot snapshot, uint64_t view, int preview = 1);
  // Waits until the camera, the options or the exposure change, or `wait` passes (an idle loop);
  // true when the exposure changed (the frame is to be shown again).
  bool wait_for_change(std::chrono::milliseconds wait);

 private:
  std::string options_json() const;       // under mutex_
  std::string set_choice(RenderChoice next);  // under mutex_: configures it or throws
  // Under mutex_: the pixel's reply; nullopt while its session's pass is aborted (no image); throws
  // for a pixel outside the image.
  std::optional<std::string> inspect_pixel(const Inspect& at) const;

  const PerspectiveCamera home_;
  const float step_;
  const FrameSaver saver_;
  const FlightRecorder recorder_;
  bool recording_ = false;     // guarded by mutex_; the frames are written outside it
  std::mutex frame_writing_;   // serialises the recorder's start, frame and stop
  const std::shared_ptr<const Image> reference_;
  double last_flip_ = -1.0;  // FLIP of the last frame it was computed for (at most once a second)
  std::chrono::steady_clock::time_point last_flip_time_{};
  mutable std::mutex mutex_;
  std::condition_variable frame_ready_, changed_;
  std::vector<RenderSession*> sessions_;
  PerspectiveCamera camera_;
  bool camera_changed_ = false;
  RenderChoice choice_;
  RenderChoice applied_choice_, taken_choice_;  // the last choice a session was made with; the one take_config took
  // The last error of a session the loop could not make (config_failed, split_failed), for the
  // frames' statistics: its number and when it came.
  std::string error_;
  uint64_t error_id_ = 0;
  std::chrono::steady_clock::time_point error_time_{};
  void set_error(const std::string& message);  // under mutex_
  std::optional<RenderConfig> config_changed_;
  std::string split_label_;  // the right half's integrator and filter; empty: no split screen
  std::optional<std::optional<RenderConfig>> split_changed_;
  const double fps_;          // of the animation; 0: the scene does not move
  bool playing_ = false;
  uint64_t animation_frame_ = 0;  // the time shown is animation_frame_ / fps_
  bool time_changed_ = false;
  std::string shown_ = "image";  // "image" or a debug image's name
  double exposure_stops_ = 0.0;
  ToneMap tone_ = ToneMap::clip;
  bool exposure_changed_ = false;
  // The newest frame before encoding, and the newest encoded one.
  struct Pending {
    uint64_t sequence = 0;
    std::shared_ptr<const Image> image;
    Display display;
    std::string stats_json;
    std::string label;  // FrameSaver's
  };
  Pending latest_;
  Frame encoded_;
  std::chrono::steady_clock::time_point view_start_ = std::chrono::steady_clock::now();
};

}  // namespace pathspace::viewer
