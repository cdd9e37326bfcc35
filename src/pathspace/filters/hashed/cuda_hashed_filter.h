// CudaHashedFilter: hashed path space filtering (Binder, Fricke, Keller 2021, sec. 3.1-3.4 and 4)
// on an NVIDIA GPU, over a vertex buffer in device memory (DeviceVertexBuffer::view(), or a CUDA
// path tracer's). The pass is run_hashed_pass (hashed_pass.h), shared with the CPU filter; its steps
// here are kernels: clear the table, keys + accumulation with warp aggregation, settling of
// overflowing probe windows when any overflowed, lookup. With --temporal integrate or ema (sec. 3.4)
// the keys stay from pass to pass and frame to frame: new cells take their finer or coarser voxels'
// history (3.4.2), lookups blend with the history (3.4.1), and after each pass every probe window
// is folded and evicted on the device (3.4.3). The per-vertex and per-window steps are the CPU
// filter's (filters/hashed/hashed_filter_steps.h, filters/hashed/temporal_steps.h) and sums are integers, so the
// filtered values equal HashedFilter's bit for bit (docs/hashed-filter.md, "The GPU filter").
// Includable from plain C++ (g++ with the CUDA include path); the kernels are in
// cuda_hashed_filter.cu.
#pragma once

#include <cuda_runtime_api.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "pathspace/camera/perspective_camera.h"
#include "pathspace/filters/hashed/hashed_filter_settings.h"
#include "pathspace/filters/hashed/hashed_filter_steps.h"
#include "pathspace/filters/path_space_filter.h"
#include "pathspace/filters/hashed/temporal_steps.h"
#include "pathspace/filters/vertex_buffer_view.h"
#include "pathspace/filters/hashed/hashed_filter_stats.h"
#include "pathspace/filters/cuda_vertex_buffer.h"
#include "pathspace/parallel/device_buffer.h"

namespace pathspace::gpu {

// A PathSpaceFilter, so that a CUDA path tracer hands it with its table to the next frame's
// (Integrator::carried_filter), and so that any integrator could filter a host buffer with it.
class CudaHashedFilter final : public PathSpaceFilter {
 public:
  // The table and probe limit of HashedFilter for this many pixels. Throws pathspace::Error for what
  // the GPU filter does not do and for settings HashedFilter rejects (check_hashed_filter_settings).
  CudaHashedFilter(const HashedFilterSettings& settings, const PerspectiveCamera& camera, size_t pixels);
  // The same with the camera's projected pixel size at distance 1 (2 tan_y / height) given directly
  // (vertex buffer files carry it; filters/vertex_buffer_file.h).
  CudaHashedFilter(const HashedFilterSettings& settings, float pixel_angle, size_t pixels);

  const char* name() const override { return "hashed"; }
  // device_filtered[slot] receives the filtered contribution of every valid record slot of
  // device_buffer (device memory, device_buffer.slots() elements). Returns when the pass is done
  // (the statistics are read back).
  void filter(const VertexBufferView& device_buffer, uint64_t seed, uint32_t pass, Rgb* device_filtered,
              cudaStream_t stream = 0);
  // The same for a buffer in host memory: uploaded, filtered, the values downloaded.
  void filter(const VertexBuffer& buffer, uint64_t seed, uint32_t pass, SlotValues* filtered) override;
  // A new frame (sec. 3.4): the field of view may change, the image size may not.
  void begin_frame(const PerspectiveCamera& camera) override;
  uint32_t frame_warm_up() const override { return history_.size() ? kTemporalWarmUpFrames : 0; }
  std::string distribution_limit() const override { return history_.size() ? kTemporalDistributionLimit : std::string(); }
  // The statistics, and with --temporal the keys with their priorities and the histories, under the
  // CPU filter's names for the table (HashedFilter::save_state).
  void save_state(StateWriter& out) const override;
  void load_state(StateReader& in) override;

  // The CPU filter's statistics struct with device cuda, reported under the same names
  // (hashed_filter_statistics.cpp).
  const HashedFilterStats& stats() const { return stats_; }
  void reset_stats() { stats_ = stats_.fresh(); }
  void statistics(Statistics& out) const override;
  uint64_t cells() const { return cells_; }
  // Device pointers to the table of the last pass (tests read it back).
  VoxelHashTableView table() const;
  const HashedStepSettings& step_settings() const { return steps_; }

 private:
  class PassSteps;  // the steps of run_hashed_pass, over this object (cuda_hashed_filter.cu)
  // True when cells changed hands.
  bool settle_overflows(const VertexBufferView& b, uint64_t pass_hash, uint64_t failures, cudaStream_t stream);
  // Sec. 3.4.2 and 3.4.3 on the device (--temporal).
  void transfer_levels(const VertexBufferView& b, uint64_t pass_hash, uint32_t step, cudaStream_t stream);
  void end_step(uint32_t step, cudaStream_t stream);
  VoxelHashTableView coarse_table() const;
  std::vector<unsigned long long> read_counters(cudaStream_t stream) const;

  HashedFilterSettings settings_;
  HashedStepSettings steps_;
  uint64_t cells_ = 0;
  size_t pixels_ = 0;
  // --temporal: per cell, the history and the level transfer's claim (0 free, 1 claimed, 2 with a
  // transfer) and transfer; empty otherwise.
  DeviceBuffer<VoxelHistory> history_, transferred_;
  DeviceBuffer<uint32_t> transfer_claimed_;
  // filter(const VertexBuffer&): the host buffer's copy and the values.
  DeviceVertexBuffer host_buffer_;
  DeviceBuffer<Rgb> host_filtered_;
  DeviceBuffer<uint32_t> fingerprints_, coarse_fingerprints_;
  DeviceBuffer<VoxelCell> cells_buffer_, coarse_cells_;
  DeviceBuffer<int32_t> slots_, coarse_slots_;  // per record slot: table cell or kSlot*
  DeviceBuffer<unsigned long long> counters_;  // per pass, kCopies copies (cuda_hashed_filter.cu)
  DeviceBuffer<uint8_t> reassigned_;            // settling: cells that changed hands
  HashedFilterStats stats_;
};

}  // namespace pathspace::gpu
