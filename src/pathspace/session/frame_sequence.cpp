#include "pathspace/session/frame_sequence.h"

#include <chrono>

#include "pathspace/accel/accel.h"
#include "pathspace/base/error.h"
#include "pathspace/scene/scene.h"
#include "pathspace/scene/scene_validation.h"

namespace pathspace {

namespace {
double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}
}  // namespace

uint64_t render_frames(const Animation& animation, const RenderConfig& config, FrameRange range, uint32_t passes,
                       const std::function<bool(const FrameResult&)>& on_frame,
                       const std::function<void(RenderSession&)>& on_session) {
  if (range.last < range.first) throw Error("the last frame comes before the first");
  if (passes == 0) throw Error("a frame needs at least one pass");
  std::unique_ptr<RenderSession> session;
  std::shared_ptr<const Accel> previous;
  uint64_t rendered = 0;
  for (uint64_t frame = range.first; frame <= range.last; ++frame) {
    FrameResult result;
    result.frame = frame;
    auto t0 = std::chrono::steady_clock::now();
    // The scene is made anew every frame; its acceleration structure reuses the previous frame's for
    // the geometry that does not move (Scene::first_moving_triangle, accel/accel.h).
    auto scene = std::make_shared<const Scene>(animation.at_frame(frame));
    std::vector<std::string> warnings;
    validate_scene(*scene, &warnings);  // before Embree sees the frame's values (the session reports the warnings)
    auto accel = std::make_shared<const Accel>(*scene, previous.get());
    result.scene_seconds = seconds_since(t0);
    result.static_geometry_reused = accel->reused_static_part();
    previous = accel;
    if (!session) {
      session = std::make_unique<RenderSession>(scene, accel, config);
      if (on_session) on_session(*session);
    }
    session->begin_frame(scene, accel, frame);
    t0 = std::chrono::steady_clock::now();
    const RunResult run = session->run(RunLimit::for_passes(passes));
    result.render_seconds = seconds_since(t0);
    result.snapshot = session->snapshot();
    ++rendered;
    if (!on_frame(result) || run.cancelled) break;
  }
  return rendered;
}

}  // namespace pathspace
