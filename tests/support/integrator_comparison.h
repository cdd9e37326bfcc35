// Shared by the consistency tests that compare integrators with each other: rendering a scene with
// a named integrator into mean and variance-of-the-mean images, masking pixels, the per-pixel
// z-test with evidence images on failure, and the PATHSPACE_TEST_SEED offset.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "pathspace/accel/accel.h"
#include "pathspace/film/image.h"
#include "pathspace/filters/hashed/hashed_filter_settings.h"
#include "pathspace/integrators/bpt/bpt_settings.h"
#include "pathspace/integrators/lt/lt_settings.h"
#include "pathspace/integrators/pclt/pclt_settings.h"
#include "pathspace/integrators/pt/pt_settings.h"
#include "pathspace/integrators/sppm/sppm_settings.h"
#include "pathspace/scene/scene.h"
#include "pathspace/session/render.h"

namespace pathspace::testing {

struct Rendered {
  Image mean, variance;
};

// Renders `passes` passes with `config` (integrator, settings, filter, seed, threads); checks that
// no sample was dropped; collects the AOVs when asked.
Rendered render_integrator(const Scene& scene, const Accel& accel, const RenderConfig& config, uint32_t passes,
                           std::vector<NamedImage>* aovs = nullptr);
Rendered render_integrator(const Scene& scene, const RenderConfig& config, uint32_t passes,
                           std::vector<NamedImage>* aovs = nullptr);

// `integrator` with its default settings.
inline RenderConfig default_config(const std::string& integrator, uint64_t seed) {
  RenderConfig config;
  config.integrator = integrator;
  config.seed = seed;
  return config;
}

// `config` with `threads` threads (<= 0: all cores).
inline RenderConfig with_threads(RenderConfig config, int threads) {
  config.threads = threads;
  return config;
}

// Zeroes mean and variance where mask[i] is set (those pixels cannot fail a comparison).
void apply_mask(Rendered* r, const std::vector<bool>& mask);

// Per-pixel z-test of two renders (support/statistics.h image_z_test, alpha_pixel 1e-3), its numbers
// printed for the record; on failure writes both images to the evidence folder and lists the worst
// pixels.
void expect_same_image(const Rendered& a, const Rendered& b, const std::string& what, double alpha_image,
                       const std::string& name_a = "a", const std::string& name_b = "b");

// The exact image of a closed-form radiance as the camera's one-pixel box filter sees it: each
// pixel's mean of radiance(hit) over an n x n midpoint grid of camera rays through its footprint
// (hit is nullptr where the ray meets nothing).
Image footprint_average(const Scene& scene, const Accel& accel, int n, const std::function<Rgb(const SurfaceHit*)>& radiance);

// Per-pixel z-test of a render against an exact image (variance 0; support/statistics.h
// image_z_test, alpha_pixel 1e-3). With whole_image false only the failing-pixel count is judged
// (filtered pixels share voxels, so the image mean's test would assume an independence they lack).
void expect_matches_exact(const Rendered& r, const Image& expected, const std::string& what, double alpha_image,
                          bool whole_image = true);

// Pixels where any of 3x3 probe rays first hits a surface without a non-delta lobe (mirror, glass):
// light paths cannot reach the camera through those. With a thin lens each probe goes through 9
// lens points (centre and near the rim).
std::vector<bool> specular_first_hit_mask(const Scene& scene, const Accel& accel);

// SPPM's "smooth pixel" mask (sppm_pt_consistency_test.cpp, gathering_bpt_consistency_test.cpp): true where
// 4x4 primary rays across the pixel all hit the same plane with the same non-delta, non-specular,
// non-emitting material, and 8 probe rays along that plane from each hit travel `reach` unoccluded,
// i.e. where a gather ball of radius <= reach sees one flat surface (no edges, contacts, curved or
// delta surfaces). With exclude_ceiling, pixels that see a downward-facing surface are dropped too.
// With a thin lens the 4x4 primary rays go through 9 lens points each (a pixel sees a blend).
// With exclude_glossy, pixels that see a surface with a glossy lobe are dropped too.
std::vector<bool> smooth_pixels(const Scene& scene, const Accel& accel, float reach, bool exclude_ceiling,
                                bool exclude_glossy = false);

// The kept pixels (keep[i]) as a one-row image, so that the z-test counts only those.
Image compact_pixels(const Image& img, const std::vector<bool>& keep);

// PATHSPACE_TEST_SEED=k shifts the seeds of the statistical comparisons (robustness reruns).
uint64_t test_seed_base();

// The seed test_seed_base() + seed.
uint64_t test_seed(uint64_t seed);

}  // namespace pathspace::testing
