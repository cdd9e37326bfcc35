// What both hashed filters (HashedFilter on the CPU, filters/hashed/cuda_hashed_filter.h on the GPU) check of
// their settings, and the table size they derive from them, in one place: the GPU filter's output
// equals the CPU's bit for bit only with the same table. Header-only (no TBB), so the standalone
// GPU benchmark (bench/cuda) compiles it.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>

#include "pathspace/base/error.h"
#include "pathspace/camera/perspective_camera.h"
#include "pathspace/filters/hashed/hashed_filter_settings.h"
#include "pathspace/filters/hashed/hashed_filter_stats.h"
#include "pathspace/filters/hashed/voxel_hash_table.h"

namespace pathspace {

// Throws pathspace::Error naming the option. The one check of both filters: what the GPU filter
// lacks is refused here, so a feature added to the CPU filter is either built on the GPU or named
// below.
inline void check_hashed_filter_settings(const HashedFilterSettings& s, FilterDevice device) {
  if (!(s.key.psf_scale > 0.f)) throw Error("the filter scale (--psf-scale) must be positive");
  if (s.key.normal_bins < 1 || s.key.direction_bins < 1 || s.key.normal_bins > kMaxKeyBins || s.key.direction_bins > kMaxKeyBins)
    throw Error("normal and direction bins must be between 1 and " + std::to_string(kMaxKeyBins) + " per axis");
  if (s.max_probes < 1) throw Error("the probe limit must be at least 1");
  if (s.temporal.enabled() && (s.multi_level || s.neighbour_search || s.adaptive))
    throw Error("--temporal keeps one level of voxels: it does not combine with --psf-neighbours, --psf-multi-level or --psf-adaptive");
  if (device != FilterDevice::cuda) return;
  if (s.temporal.mode == TemporalMode::hybrid)
    throw Error("--temporal hybrid re-traces the previous frame's paths, which the GPU path tracer does not do: "
                "use --temporal integrate or ema with --device cuda");
  if (s.debug_images) throw Error("the GPU hashed filter writes no debug images: --aov is not supported with --device cuda");
  if (s.adaptive)  // the coarse cells' sums of squares are not accumulated on the device
    throw Error("the GPU hashed filter has no adaptive resolution: --psf-adaptive is not supported with --device cuda");
  if (s.aa_paths > 0)  // the CUDA path tracer traces no query-only paths
    throw Error("the GPU path tracer traces no query-only paths: --psf-aa-paths is not supported with --device cuda");
}

// The projected size of one pixel at distance 1 (sec. 4: voxels are "s-times the projected size of
// a pixel"); the field of view may change from frame to frame.
inline float hashed_filter_pixel_angle(const PerspectiveCamera& camera) { return 2.f * camera.tan_y / float(camera.height); }

// Cells of the table (each level's) for an image of `pixels` pixels: table_factor per pixel,
// rounded up to a power of two (voxel_table_cells).
inline uint64_t hashed_filter_table_cells(const HashedFilterSettings& s, size_t pixels) {
  return voxel_table_cells(uint64_t(std::max(1.0, double(s.table_factor) * double(pixels))));
}

}  // namespace pathspace
