// FNV-1a, 64 bit: a cheap, stable fingerprint of bytes (scene contents in render states and
// checkpoints), not a hash for tables (filters/hashed/voxel_key.h has those).
#pragma once

#include <cstddef>
#include <cstdint>

namespace pathspace {

inline constexpr uint64_t kFnv1a64Offset = 1469598103934665603ull;

// Continues `hash` over the bytes (start with kFnv1a64Offset).
inline uint64_t fnv1a64(const void* data, size_t size, uint64_t hash = kFnv1a64Offset) {
  const auto* bytes = static_cast<const unsigned char*>(data);
  for (size_t i = 0; i < size; ++i) hash = (hash ^ bytes[i]) * 1099511628211ull;
  return hash;
}

}  // namespace pathspace
