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
