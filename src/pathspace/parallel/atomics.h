// Integer atomic primitives on plain memory for device-safe data structures (hash grid, PCLT
// listing 1): compare-and-swap, exchange, fetch_add/or/min. On the CPU they are GCC/Clang __atomic
// builtins (work on any aligned integer, no std::atomic member needed, so structs stay plain); under
// nvcc's device pass they map to atomicCAS / atomicExch / atomicAdd / atomicOr / atomicMin.
// Read-modify-writes are acq_rel: phases (build, then query) are separated by a parallel_for join.
#pragma once

#include <cstdint>

#include "pathspace/base/platform.h"

namespace pathspace {

#if PS_DEVICE_CODE
// CUDA's 64-bit atomics take unsigned long long; uint64_t is unsigned long on LP64 hosts.
__device__ inline unsigned long long* ps_ull(uint64_t* p) { return reinterpret_cast<unsigned long long*>(p); }
#endif

// Returns the previous value; the store happened iff the return value equals `expected`.
PS_INLINE uint64_t atomic_cas(uint64_t* p, uint64_t expected, uint64_t desired) {
#if PS_DEVICE_CODE
  return atomicCAS(ps_ull(p), expected, desired);
#else
  __atomic_compare_exchange_n(p, &expected, desired, false, __ATOMIC_ACQ_REL, __ATOMIC_ACQUIRE);
  return expected;  // on failure the builtin wrote the observed value here
#endif
}

PS_INLINE uint32_t atomic_cas(uint32_t* p, uint32_t expected, uint32_t desired) {
#if PS_DEVICE_CODE
  return atomicCAS(reinterpret_cast<unsigned*>(p), expected, desired);
#else
  __atomic_compare_exchange_n(p, &expected, desired, false, __ATOMIC_ACQ_REL, __ATOMIC_ACQUIRE);
  return expected;
#endif
}

PS_INLINE uint32_t atomic_exchange(uint32_t* p, uint32_t value) {
#if PS_DEVICE_CODE
  return atomicExch(reinterpret_cast<unsigned*>(p), value);
#else
  return __atomic_exchange_n(p, value, __ATOMIC_ACQ_REL);
#endif
}

PS_INLINE uint32_t atomic_fetch_add(uint32_t* p, uint32_t value) {
#if PS_DEVICE_CODE
  return atomicAdd(reinterpret_cast<unsigned*>(p), value);
#else
  return __atomic_fetch_add(p, value, __ATOMIC_ACQ_REL);
#endif
}

PS_INLINE uint64_t atomic_fetch_add(uint64_t* p, uint64_t value) {
#if PS_DEVICE_CODE
  return atomicAdd(ps_ull(p), value);
#else
  return __atomic_fetch_add(p, value, __ATOMIC_ACQ_REL);
#endif
}

PS_INLINE uint32_t atomic_fetch_or(uint32_t* p, uint32_t bits) {
#if PS_DEVICE_CODE
  return atomicOr(reinterpret_cast<unsigned*>(p), bits);
#else
  return __atomic_fetch_or(p, bits, __ATOMIC_ACQ_REL);
#endif
}

// Keeps the smaller value; returns the previous one. x86 has no fetch_min: a CAS loop that stops as
// soon as the stored value is already smaller (the common case once a slot has seen a few values).
PS_INLINE uint64_t atomic_fetch_min(uint64_t* p, uint64_t value) {
#if PS_DEVICE_CODE
  return atomicMin(ps_ull(p), value);
#else
  uint64_t old = __atomic_load_n(p, __ATOMIC_RELAXED);
  while (value < old && !__atomic_compare_exchange_n(p, &old, value, true, __ATOMIC_ACQ_REL, __ATOMIC_RELAXED)) {
  }
  return old;
#endif
}

// Relaxed loads: a hint read before a CAS (skips the locked instruction when the answer is known).
PS_INLINE uint64_t atomic_load_relaxed(const uint64_t* p) {
#if PS_DEVICE_CODE
  return *reinterpret_cast<const volatile unsigned long long*>(p);
#else
  return __atomic_load_n(p, __ATOMIC_RELAXED);
#endif
}

PS_INLINE uint32_t atomic_load_relaxed(const uint32_t* p) {
#if PS_DEVICE_CODE
  return *reinterpret_cast<const volatile unsigned*>(p);
#else
  return __atomic_load_n(p, __ATOMIC_RELAXED);
#endif
}

}  // namespace pathspace
