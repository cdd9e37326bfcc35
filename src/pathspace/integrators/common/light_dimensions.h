// Fixed layout of sampler dimensions along a light path (LT now; BPT and PCLT light subpaths
// later), the counterpart of dimensions.h for camera paths: a dimension is a pure function of
// (path index, pass, vertex index, purpose), so switching options never reshuffles the others.
#pragma once

#include <cstdint>

#include "pathspace/base/platform.h"

namespace pathspace::light_dims {

inline constexpr uint32_t kLightSelect = 0;
inline constexpr uint32_t kEmitPos = 1;  // and kEmitPos + 1
inline constexpr uint32_t kEmitDir = 3;  // and kEmitDir + 1
inline constexpr uint32_t kFirstVertex = 5;
inline constexpr uint32_t kPerVertex = 4;

// Offsets inside a vertex's block.
inline constexpr uint32_t kLobe = 0;
inline constexpr uint32_t kBsdfU = 1;  // and kBsdfU + 1
inline constexpr uint32_t kRoulette = 3;

// Thin-lens samples of the camera connections (LT, BPT t = 1, PCLT projection), two dimensions
// each, in a range far above the per-vertex blocks: connection 0 is the emitter's (s = 1, t = 1),
// connection v + 1 that of vertex v. Pinhole renders never read them.
inline constexpr uint32_t kLensFirst = 0x40000000u;
PS_HD inline constexpr uint32_t lens(uint32_t connection) { return kLensFirst + 2u * connection; }
// The light path's time in a scene that moves (scene/motion.h), below the lens range and far above
// the per-vertex blocks: still scenes never read it.
inline constexpr uint32_t kTime = 0x3fffff00u;
// The seed of the light path's stream of numbers in media (Sampler::bits): scenes with media only.
inline constexpr uint32_t kMediumStream = 0x3fffff01u;

PS_HD inline constexpr uint32_t vertex(uint32_t index, uint32_t offset) { return kFirstVertex + index * kPerVertex + offset; }

}  // namespace pathspace::light_dims
