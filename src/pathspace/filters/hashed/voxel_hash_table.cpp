#include "pathspace/filters/hashed/voxel_hash_table.h"

#include <cmath>
#include <cstdlib>
#include <cstring>

#include "pathspace/base/error.h"
#include "pathspace/parallel/parallel_for.h"

namespace pathspace {

namespace {

constexpr size_t kLineBytes = 64;

template <typename T>
T* allocate_lines(uint64_t count) {
  const size_t bytes = (size_t(count) * sizeof(T) + kLineBytes - 1) / kLineBytes * kLineBytes;
  void* p = std::aligned_alloc(kLineBytes, bytes);
  if (!p) throw Error("out of memory allocating a voxel hash table of " + std::to_string(bytes >> 20) + " MiB");
  return static_cast<T*>(p);
}

}  // namespace

void VoxelHashTable::FreeDeleter::operator()(void* p) const { std::free(p); }

VoxelHashTable::VoxelHashTable(uint64_t cells, int max_probes) {
  if (max_probes < 1) throw Error("the probe limit must be at least 1");
  const uint64_t n = voxel_table_cells(cells);
  fingerprints_.reset(allocate_lines<uint32_t>(n));
  cells_.reset(allocate_lines<VoxelCell>(n));
  view_.fingerprints = fingerprints_.get();
  view_.cells = cells_.get();
  view_.mask = n - 1;
  view_.max_probes = max_probes;
  clear();
}

void VoxelHashTable::clear() {
  const uint64_t n = cells();
  constexpr size_t kChunk = 1 << 16;
  parallel_for(size_t(n), kChunk, [&](size_t begin, size_t end) {
    std::memset(view_.fingerprints + begin, 0, (end - begin) * sizeof(uint32_t));
    std::memset(static_cast<void*>(view_.cells + begin), 0, (end - begin) * sizeof(VoxelCell));
  });
}

void VoxelHashTable::clear_sums() {
  constexpr size_t kChunk = 1 << 16;
  parallel_for(size_t(cells()), kChunk, [&](size_t begin, size_t end) {
    std::memset(static_cast<void*>(view_.cells + begin), 0, (end - begin) * sizeof(VoxelCell));
  });
}

void VoxelHashTable::clear_listed(const std::vector<uint32_t>& slots, bool keys) {
  for (const uint32_t s : slots) {
    view_.cells[s] = VoxelCell{};
    if (keys) view_.fingerprints[s] = kEmptyFingerprint;
  }
}

VoxelTableOccupancy VoxelHashTable::occupancy() const {
  VoxelTableOccupancy o;
  o.cells = cells();
  const uint64_t window = view_.max_probes <= kFingerprintsPerLine ? kFingerprintsPerLine : uint64_t(view_.max_probes);
  double pairs = 0.0;
  for (uint64_t w = 0; w < o.cells; w += window) {
    uint64_t n = 0;
    for (uint64_t i = w; i < w + window && i < o.cells; ++i) n += view_.fingerprints[i] != kEmptyFingerprint;
    o.occupied += n;
    pairs += 0.5 * double(n) * double(n > 0 ? n - 1 : 0);
  }
  const int bits = view_.kept_across_frames() ? kPriorityShift : 32;
  o.expected_fingerprint_collisions = pairs / (std::ldexp(1.0, bits) - 1.0);
  return o;
}

}  // namespace pathspace
