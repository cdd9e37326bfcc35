// The record slots of a range of paths in blocks of kVoxelKeyBatchSize, with their voxel keys and
// hashes computed a block at a time (filters/hashed/voxel_key_batch.h): the hashed filter's accumulation
// and its anti-aliasing queries both walk a vertex buffer this way, so both get the batched keys.
// Keys equal key_for_pass (hashed_filter_keys.h) bit for bit.
#pragma once

#include <cstddef>
#include <cstdint>

#include "pathspace/filters/hashed/hashed_filter_keys.h"
#include "pathspace/filters/hashed/voxel_key_batch.h"

namespace pathspace {

class VoxelKeyBlocks {
 public:
  // Paths [begin, end) of `b`; `pass_hash` is the jitter of the pass or query round.
  VoxelKeyBlocks(const VoxelKeySettings& settings, const VertexBufferView& b, size_t begin, size_t end, uint64_t pass_hash,
                 VoxelKeyIsa isa)
      : settings_(settings), b_(b), path_(begin), end_(end), pass_hash_(pass_hash), isa_(isa) {}

  // Fills the next block: lanes [0, n) of batch() hold slot(j)'s key and hash. 0 once all are done.
  int next() {
    int n = 0;
    // Without a branch per record: every slot up to the path's last record (at least one) is
    // written to the next lane, which only advances when the slot holds a record (a quarter of
    // second-bounce paths have none, in no predictable pattern, and a mispredicted branch cost more
    // than the copy). Slots past the last record are not read: with camera-side branches
    // (VertexSelection::camera_splits) most of a path's slots are empty.
    while (n < kVoxelKeyBatchSize && path_ < end_) {
      const size_t i = b_.slot(path_, record_);
      batch_.set_input(n, key_input(b_, i), jitter_seed(pass_hash_, b_.record_stream(path_, record_)));
      slot_[n] = i;
      const int count = b_.count[path_];
      n += record_ < count ? 1 : 0;
      if (++record_ >= (count > 1 ? count : 1)) {
        record_ = 0;
        ++path_;
      }
    }
    compute_voxel_keys(settings_, n, &batch_, isa_);
    return n;
  }

  const VoxelKeyBatch& batch() const { return batch_; }
  size_t slot(int lane) const { return slot_[lane]; }

 private:
  const VoxelKeySettings& settings_;
  const VertexBufferView b_;
  size_t path_, end_;
  int record_ = 0;
  uint64_t pass_hash_;
  VoxelKeyIsa isa_;
  VoxelKeyBatch batch_;
  size_t slot_[kVoxelKeyBatchSize];
};

}  // namespace pathspace
