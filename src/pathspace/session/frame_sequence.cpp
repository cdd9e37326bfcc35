#include "pathspace/session/frame_sequence.h"

#include <algorithm>
#include <chrono>

#include <fmt/format.h>

#include "pathspace/accel/accel.h"
#include "pathspace/base/error.h"
#include "pathspace/scene/scene.h"

namespace pathspace {

namespace {
double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}
}  // namespace

bool frame_chunk(FrameRange range, FrameChunk chunk, FrameRange* mine) {
  const uint64_t n = range.count(), ranks = uint64_t(chunk.ranks), r = uint64_t(chunk.rank);
  const uint64_t begin = n * r / ranks, end = n * (r + 1) / ranks;
  if (end == begin) return false;
  *mine = {range.first + begin, range.first + end - 1};
  return true;
}

uint64_t render_frames(const Animation& animation, const RenderConfig& config, FrameRange range, uint32_t passes,
                       const std::function<bool(FrameResult&)>& on_frame,
                       const std::function<void(RenderSession&)>& on_session, FrameChunk chunk, SnapshotImages images) {
  if (range.last < range.first) throw Error("the last frame comes before the first");
  if (passes == 0) throw Error("a frame needs at least one pass");
  FrameRange mine;
  if (!frame_chunk(range, chunk, &mine)) return 0;
  std::unique_ptr<RenderSession> session;
  uint64_t rendered = 0;
  for (uint64_t frame = mine.first; frame <= mine.last; ++frame) {
    FrameResult result;
    auto t0 = std::chrono::steady_clock::now();
    // The scene is made anew every frame; the session validates it and builds its acceleration
    // structure, reusing the previous frame's for what does not move (accel/accel.h).
    try {
      auto scene = std::make_shared<const Scene>(animation.at_frame(frame));
      if (!session) {
        session = std::make_unique<RenderSession>(scene, nullptr, config);
        if (on_session) on_session(*session);
        // A later chunk starts with the warm-up frames before it (what the integrator carries).
        const uint64_t warm_up = std::min<uint64_t>(session->frame_warm_up(), mine.first - range.first);
        if (warm_up > 0) {
          frame = mine.first - warm_up;
          scene = std::make_shared<const Scene>(animation.at_frame(frame));
        }
      }
      session->begin_frame(scene, nullptr, frame);
    } catch (const Error& e) {  // say which frame: the ones before were fine
      throw Error(fmt::format("frame {} ({:g} s): {}", frame, animation.seconds_of(frame), e.what()));
    }
    result.frame = frame;
    result.scene_seconds = seconds_since(t0);
    result.static_geometry_reused = session->accel().reused_static_part();
    result.scene_warnings = session->scene_warnings();
    t0 = std::chrono::steady_clock::now();
    const RunResult run = session->run(RunLimit::for_passes(passes));
    result.render_seconds = seconds_since(t0);
    if (frame < mine.first) {  // warm-up: not reported
      if (run.cancelled) break;
      continue;
    }
    result.snapshot = session->snapshot(images);
    ++rendered;
    if (!on_frame(result) || run.cancelled) break;
  }
  return rendered;
}

}  // namespace pathspace
