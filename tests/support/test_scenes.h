// Closed scenes with known answers for furnace tests (docs/testing.md):
//  - a closed cube whose walls all emit Le and reflect with diffuse albedo a: L = Le / (1 - a)
//    (with a limit of D segments: Le (1 - a^D) / (1 - a));
//  - the inside of a diffuse sphere (radius R, albedo a) with a point light of intensity I at its
//    centre: L = (a / pi) (I / R^2) / (1 - a);
//  - the inside of an emissive diffuse sphere: L = Le / (1 - a);
//  - a diffuse plane under a constant sky: L = a L_sky (one bounce, nothing else in the scene).
// The camera sits inside looking at the walls, so every pixel has the same expected value.
#pragma once

#include "pathspace/scene/scene.h"

namespace pathspace::testing {

Scene make_furnace_box(float emission, float albedo, int resolution = 16);
Scene make_sphere_with_point_light(float radius, float albedo, float intensity, int resolution = 16);
Scene make_emissive_sphere(float radius, float emission, float albedo, int resolution = 16);
// A large diffuse square (albedo a) under a constant environment L seen from above: L_out = a L.
Scene make_plane_under_sky(float albedo, float sky, int resolution = 16);

// The Cornell box's diffuse walls, each coated in turn by one of three layered materials; with
// white_stays_diffuse the white walls keep their Lambertian material (PCLT's projection and pixel
// cache need Lambertian surfaces: through coated ones its eye paths continue by BSDF sampling alone).
// Used by the layered material test and the GPU test of features.
Scene make_coated_cornell_box(int resolution, bool smooth_coats, bool white_stays_diffuse = false);

}  // namespace pathspace::testing
