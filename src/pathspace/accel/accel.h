// The ray-casting contract every integrator uses on the CPU: nearest hit and any-hit (shadow) queries
// over a finalised Scene. The implementation (embree_accel.cpp) is the project's only user of
// Embree's ray queries (bvh_build.cpp uses its BVH builder for the device tracer, bvh_tracer.h).
// Accel satisfies the "Tracer" concept the PS_HD kernels are templated on (intersect / occluded).
#pragma once

#include <cstdint>
#include <memory>

#include "pathspace/geometry/interaction.h"
#include "pathspace/geometry/ray.h"

namespace pathspace {

class Scene;

class Accel {
 public:
  // `previous`: the Accel of the previous frame of an animation; the part of the scene that does not
  // move (Scene::first_moving_triangle, first_moving_sphere; all of it when nothing moves) is reused
  // from it when unchanged.
  explicit Accel(const Scene& scene, const Accel* previous = nullptr);
  // Whether the static part was taken from `previous` (animations; statistics and tests).
  bool reused_static_part() const;
  ~Accel();
  Accel(const Accel&) = delete;
  Accel& operator=(const Accel&) = delete;

  // Nearest hit in (ray.tmin, ray.tmax). Fills every field of *hit. Thread-safe.
  bool intersect(const Ray& ray, SurfaceHit* hit) const;
  // True when anything blocks (ray.tmin, ray.tmax). Thread-safe.
  bool occluded(const Ray& ray) const;
  // The nearest hit's distance, kInfinity when none: Embree's query alone, no SurfaceHit filled in
  // (the ray caster's own rate; bench/ray_replay_bench.cpp). Thread-safe.
  float hit_distance(const Ray& ray) const;

  // Batched queries (Embree's stream API); `coherent` marks camera-ray batches. Results equal the
  // single-ray calls bit for bit.
  void intersect_batch(const Ray* rays, SurfaceHit* hits, bool* found, uint32_t count, bool coherent) const;
  void occluded_batch(const Ray* rays, bool* blocked, uint32_t count) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace pathspace
