// Fixed layout of sampler dimensions along a path, so that a dimension is a pure function of
// (pixel, sample, vertex index, purpose) and enabling/disabling NEE or RR does not reshuffle the
// random numbers used by the other decisions.
#pragma once

#include <cstdint>

#include "pathspace/base/platform.h"

namespace pathspace::dims {

inline constexpr uint32_t kPixelX = 0;
inline constexpr uint32_t kPixelY = 1;
inline constexpr uint32_t kFirstVertex = 2;
inline constexpr uint32_t kPerVertex = 8;
// Thin-lens sample of the camera ray (and kLensU + 1): far above every per-vertex block, so a
// pinhole render, which never reads it, keeps its dimensions and images.
inline constexpr uint32_t kLensU = 0x40000000u;
// The camera path's time in a scene that moves (scene/motion.h): read only there.
inline constexpr uint32_t kTime = kLensU + 2;
// The seed of the path's stream of numbers for distance sampling and transmittance in media
// (media/free_flight.h; Sampler::bits): read only in scenes with media.
inline constexpr uint32_t kMediumStream = kLensU + 3;

// Offsets inside a vertex's block.
inline constexpr uint32_t kLightSelect = 0;
inline constexpr uint32_t kLightU = 1;  // and kLightU + 1
inline constexpr uint32_t kLobe = 3;
inline constexpr uint32_t kBsdfU = 4;   // and kBsdfU + 1
inline constexpr uint32_t kRoulette = 6;

PS_HD inline constexpr uint32_t vertex(uint32_t index, uint32_t offset) { return kFirstVertex + index * kPerVertex + offset; }

}  // namespace pathspace::dims
