// Renders the frames of an animation in order with one RenderSession, so that the path space filter
// and its table carry from frame to frame (2021 paper sec. 3.4; --temporal of the hashed filter).
// The CLI's `render --frames`, the temporal study and the tests all render sequences through it.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "pathspace/scene/animation.h"
#include "pathspace/session/render_session.h"

namespace pathspace {

struct FrameRange {
  uint64_t first = 0, last = 0;  // inclusive
  uint64_t count() const { return last - first + 1; }
};

struct FrameResult {
  uint64_t frame = 0;
  RenderSnapshot snapshot;     // the frame's image, variance and statistics (the filter's over all frames so far)
  double scene_seconds = 0.0;  // building the frame's scene and its acceleration structure
  bool static_geometry_reused = false;  // the acceleration structure of what does not move came from the previous frame
  std::vector<std::string> scene_warnings;  // of the frame's scene validation (RenderSession::scene_warnings)
  double render_seconds = 0.0;
};

// Frames dealt to the processes of a distributed render (docs/distributed.md): process `rank` of
// `ranks` takes a contiguous chunk of the range, chunks in rank order, sizes differing by at most
// one; false when the range has fewer frames than `rank` + 1.
struct FrameChunk {
  int rank = 0, ranks = 1;
};
bool frame_chunk(FrameRange range, FrameChunk chunk, FrameRange* mine);

// Renders `range` with `passes` passes (samples per pixel) per frame. on_frame gets each frame as it
// is done (it may move the snapshot out: the next frame's replaces it) and returns false to stop the
// sequence; cancel() of the session it gets likewise stops it after the current pass (that frame is
// then still reported, with fewer passes).
// With a chunk, only the chunk's frames are reported, after Integrator::frame_warm_up frames before
// it (within the range), which are rendered and not reported. Returns the number reported.
// `images`: what each frame's snapshot holds (a sequence at 1 spp has no variance to speak of).
uint64_t render_frames(const Animation& animation, const RenderConfig& config, FrameRange range, uint32_t passes,
                       const std::function<bool(FrameResult&)>& on_frame,
                       const std::function<void(RenderSession&)>& on_session = {}, FrameChunk chunk = {},
                       SnapshotImages images = SnapshotImages::mean_and_variance);

}  // namespace pathspace
