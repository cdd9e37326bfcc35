// Scenes with participating media for the furnace and consistency tests (docs/media.md):
//  - the Cornell box filled with fog: homogeneous and chromatic, or a chromatic grid inside the box;
//  - the Cornell box with a sphere of smoke (a surface that only bounds the medium) or a
//    translucent sphere (a rough dielectric boundary with a scattering interior);
//  - a furnace: a sphere of non-absorbing medium (albedo 1) under a constant environment, bounded
//    by an interface or by smooth glass; every pixel sees the environment's radiance exactly;
//  - an absorbing slab in front of an emitter (transmittance exp(-sigma_t d));
//  - single scattering: the camera in an infinite homogeneous medium with a point light.
#pragma once

#include "pathspace/scene/scene.h"

namespace pathspace::testing {

Scene make_fog_cornell_box(int width, int height, bool grid);
Scene make_smoke_sphere_box(int width, int height);
Scene make_translucent_sphere_box(int width, int height);
Scene make_medium_furnace(int resolution, bool glass_boundary, float sky);

// An emitting square (radiance le, facing the camera) seen through an absorbing slab one unit thick
// (z in [-1, 0], sigma_s 0, bounded by surfaces that only bound media): a camera ray of direction d
// sees le exp(-sigma_a / |d.z|).
Scene make_absorbing_slab(int resolution, const Rgb& sigma_a, float le);

// The single-scattering scene and its parameters (the quadrature in the test reads them).
struct SingleScattering {
  Rgb sigma_a{0.05f, 0.1f, 0.02f}, sigma_s{0.3f, 0.2f, 0.4f};
  float g = 0.4f;
  Vec3 light{0.5f, 1.f, 3.f};
  Rgb intensity{20.f, 20.f, 20.f};
};
Scene make_single_scattering_scene(int resolution, const SingleScattering& p);

}  // namespace pathspace::testing
