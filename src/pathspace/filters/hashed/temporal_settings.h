// Options of the hashed filter's reuse of its table across passes and frames (2021 paper sec. 3.4).
#pragma once

#include <cstdint>

namespace pathspace {

// Sec. 3.4.1: how a voxel's earlier average c_old (over N_old vertices) and this step's c_new (over
// N_new) combine.
enum class TemporalMode : uint8_t {
  off,        // every pass starts from an empty table
  integrate,  // alpha = N_old / (N_old + N_new): true temporal integration of static content
  ema,        // c = alpha c_old + (1 - alpha) c_new with a fixed alpha (--temporal-alpha)
  hybrid,     // integrate where re-traced paths show no change, down to alpha = 0 where they do (fig. 9c)
};

// Sec. 3.4.3: which cells leave the table between steps.
enum class EvictionPolicy : uint8_t {
  priority,  // the lowest fingerprint word, whose top bits hold a priority (recency, then count)
  lru,       // the least recently used
  stale,     // SHaRC's rule: every cell unused for --temporal-stale-frames steps, however full the table
};

struct TemporalSettings {
  TemporalMode mode = TemporalMode::off;
  float alpha = 0.8f;        // ema: weight of the old average
  int max_frames = 0;        // history cap: N_old <= max_frames * N_new (0: no cap)
  EvictionPolicy eviction = EvictionPolicy::priority;
  float occupancy = 0.75f;   // priority, lru: each probe window is evicted down to this fill
  int stale_frames = 32;     // stale: steps without use before a cell goes
  // hybrid: the share of pixels whose previous-frame path is re-traced each frame (the pixels take
  // turns, so every pixel is probed once in 1 / probe_fraction frames), and the relative change of a
  // voxel's probed contributions at which alpha reaches 0.
  float probe_fraction = 0.125f;
  float change_threshold = 0.25f;
  // hybrid, beyond the paper: before blending, a probed voxel's history is scaled by the ratio of its
  // re-traced paths' luminance now to before (at most kMaxRectification), a ratio estimator of
  // how much the voxel's mean changed, so that what is kept of the history follows the change.
  bool rectify = false;
  // Sec. 3.4.2: a voxel new to the table whose point had history at another level of detail (the
  // camera moved) starts from it: the sums of its finer voxels as they are, or its coarser voxel's
  // average with finer_weight times that voxel's weight (a compromise: less noise, some blur).
  bool level_transfer = true;
  float finer_weight = 0.125f;

  bool enabled() const { return mode != TemporalMode::off; }
};

// --temporal-rectify: the largest factor by which a history is scaled up in one step (a voxel that
// was nearly dark before is reset by its change instead).
inline constexpr float kMaxRectification = 4.f;

// Frames in chunks (docs/distributed.md): the voxel histories start from the 8 frames before a
// chunk, the cycle in which the hybrid's probes (1/8 of the pixels a frame) visit every pixel once;
// integration weights are then N/(N+1) >= 8/9.
inline constexpr uint32_t kTemporalWarmUpFrames = 8;
// Why a pass of a filter with --temporal cannot be split between processes.
inline constexpr const char* kTemporalDistributionLimit = "--temporal carries the voxel histories from pass to pass";

}  // namespace pathspace
