// The sampled camera side shared by every integrator: the camera ray of one camera path (jittered
// raster position, lens point) and the lens samples of light-path camera connections, at the fixed
// dimensions of dimensions.h / light_dimensions.h. A pinhole reads no lens dimension.
#pragma once

#include "pathspace/camera/perspective_camera.h"
#include "pathspace/integrators/common/dimensions.h"
#include "pathspace/integrators/common/light_dimensions.h"
#include "pathspace/sampling/sampler.h"

namespace pathspace {

// Two uniform numbers at dimensions (dim, dim + 1), or (0, 0) for a pinhole (unused there).
PS_HD inline Point2 camera_lens_sample(const PerspectiveCamera& cam, const Sampler& sampler, uint32_t dim) {
  if (cam.is_pinhole()) return {0.f, 0.f};
  return {sampler.at(dim), sampler.at(dim + 1)};
}

// The camera ray of the camera path through `pixel` (box filter: uniform in the pixel and the lens).
PS_HD inline Ray sample_camera_ray(const PerspectiveCamera& cam, const Sampler& sampler, uint32_t pixel) {
  const float rx = float(pixel % uint32_t(cam.width)) + sampler.at(dims::kPixelX);
  const float ry = float(pixel / uint32_t(cam.width)) + sampler.at(dims::kPixelY);
  return cam.generate_ray(rx, ry, camera_lens_sample(cam, sampler, dims::kLensU));
}

// Lens sample of a light path's camera connection (0: the emitter, v + 1: light vertex v).
PS_HD inline Point2 connection_lens_sample(const PerspectiveCamera& cam, const Sampler& sampler, uint32_t connection) {
  return camera_lens_sample(cam, sampler, light_dims::lens(connection));
}

}  // namespace pathspace
