// The sampled camera side shared by every integrator: the camera ray of one camera path (jittered
// raster position, lens point) and the lens samples of light-path camera connections, at the fixed
// dimensions of dimensions.h / light_dimensions.h. A pinhole reads no lens dimension.
#pragma once

#include "pathspace/camera/perspective_camera.h"
#include "pathspace/integrators/common/dimensions.h"
#include "pathspace/integrators/common/light_dimensions.h"
#include "pathspace/sampling/sampler.h"
#include "pathspace/scene/motion.h"

namespace pathspace {

// Two uniform numbers at dimensions (dim, dim + 1), or (0, 0) for a pinhole (unused there).
PS_HD inline Point2 camera_lens_sample(const PerspectiveCamera& cam, const Sampler& sampler, uint32_t dim) {
  if (cam.is_pinhole()) return {0.f, 0.f};
  return {sampler.at(dim), sampler.at(dim + 1)};
}

// The camera ray of the camera path through `pixel` at `time` (scene/motion.h; camera_path_time):
// its raster position drawn from the camera's pixel filter around the pixel's centre (filter
// importance sampling, camera/pixel_filter.h), its lens point uniform on the lens.
PS_HD inline Ray sample_camera_ray(const PerspectiveCamera& cam, const Sampler& sampler, uint32_t pixel, float time) {
  const Point2 r = sample_filter_raster(cam.filter, pixel % uint32_t(cam.width), pixel / uint32_t(cam.width),
                                        sampler.at(dims::kPixelX), sampler.at(dims::kPixelY));
  Ray ray = cam.generate_ray(r.x, r.y, camera_lens_sample(cam, sampler, dims::kLensU));
  ray.time = time;
  return ray;
}

// The camera ray of the camera path through `pixel` at `time`, from the camera at that time.
PS_HD inline Ray sample_camera_ray(const SceneView& scene, const Sampler& sampler, uint32_t pixel, float time) {
  if (!scene.camera_moves) return sample_camera_ray(scene.camera, sampler, pixel, time);  // no copy of the camera
  return sample_camera_ray(camera_at(scene, time), sampler, pixel, time);
}

// The time of a camera path (uniform over the shutter in a scene that moves, else 0).
PS_HD inline float camera_path_time(const SceneView& scene, const Sampler& sampler) {
  return sample_time(scene, sampler, dims::kTime);
}

// The time shared by every path of a pass, for integrators whose camera and light paths meet through
// a pass-wide structure (SPPM's photons, PCLT's pixel cache): uniform over the shutter per pass, from
// a sampler stream no pixel or light path uses.
PS_HD inline float pass_time(const SceneView& scene, uint64_t seed, uint32_t pass) {
  return sample_time(scene, Sampler(seed, ~uint64_t(0), pass), dims::kTime);
}

// Lens sample of a light path's camera connection (0: the emitter, v + 1: light vertex v).
PS_HD inline Point2 connection_lens_sample(const PerspectiveCamera& cam, const Sampler& sampler, uint32_t connection) {
  return camera_lens_sample(cam, sampler, light_dims::lens(connection));
}

}  // namespace pathspace
