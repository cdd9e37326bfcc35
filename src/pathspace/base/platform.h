// Portability macros: code marked PS_HD compiles for the host and, under nvcc, for the device.
// Kernel-side code (the headers the nvcc check in src/pathspace/cuda/ compiles) is written in the
// device-safe subset described in docs/architecture.md §4.
#pragma once

#if defined(__CUDACC__)
#define PS_HD __host__ __device__
#define PS_HOST __host__
#else
#define PS_HD
#define PS_HOST
#endif

#if defined(__CUDA_ARCH__)
#define PS_DEVICE_CODE 1
#else
#define PS_DEVICE_CODE 0
#endif

#define PS_INLINE PS_HD inline

// PS_INLINE, but kept out of line in device code: for a rarely taken branch of a hot loop or a
// large function called from many places, whose registers and stack would otherwise weigh on every
// thread of the kernel that inlines it (docs/gpu.md, "Register and stack pressure"). Host code is
// inlined as the compiler sees fit.
#if defined(__CUDA_ARCH__)
#define PS_INLINE_HOST_ONLY PS_HD __noinline__
#else
#define PS_INLINE_HOST_ONLY PS_HD inline
#endif
