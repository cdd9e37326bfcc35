// GGX rough conductor — PLACEHOLDER being implemented (see bsdf.h). Returns no scattering for now.
#pragma once

#include "pathspace/materials/bsdf_sample.h"
#include "pathspace/materials/material.h"
#include "pathspace/sampling/warps.h"

namespace pathspace::rough_conductor {

PS_INLINE Rgb eval(const Material&, const Vec3&, const Vec3&, TransportMode) { return {}; }
PS_INLINE float pdf(const Material&, const Vec3&, const Vec3&, TransportMode) { return 0.f; }
PS_INLINE bool sample(const Material&, const Vec3&, float, Point2, TransportMode, BsdfSample*) { return false; }

}  // namespace pathspace::rough_conductor
