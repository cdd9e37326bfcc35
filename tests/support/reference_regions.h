// Comparing a render with a published reference image (Bitterli's TungstenRender.exr) on image
// regions: the reference is box-downsampled to the render's pixel grid, and each region's mean is
// z-tested per channel with sigma^2 = Var(render's region mean) + (allowance * reference mean)^2.
// The allowance covers what differs by design (Tungsten's tent filter and material models,
// spectral versus RGB, the reference's own noise); the tests state theirs and why.
#pragma once

#include <string>
#include <vector>

#include "pathspace/film/image.h"
#include "support/integrator_comparison.h"

namespace pathspace::testing {

struct ImageRegion {
  const char* name;
  float x0, y0, x1, y1;  // fractions of the image, y down
};

// Bitterli's Cornell box (pbrt-v4 and Mitsuba forms): diffuse regions of the back and side walls.
inline const std::vector<ImageRegion> kCornellDiffuseWalls = {{"back wall", 0.55f, 0.25f, 0.75f, 0.45f},
                                                              {"back wall upper left", 0.2f, 0.15f, 0.4f, 0.3f},
                                                              {"red wall", 0.03f, 0.3f, 0.12f, 0.6f},
                                                              {"green wall", 0.89f, 0.3f, 0.97f, 0.6f}};

// The mean of a region of `img` per channel; non-finite pixels are skipped (some references hold NaN).
Rgb region_mean(const Image& img, const ImageRegion& region);

// `reference` box-filtered down to width x height; its size must be an integer multiple.
Image downsample_box(const Image& reference, int width, int height);

// GoogleTest expectations for every region and channel, Šidák-corrected to `family_alpha`; prints
// each comparison (ours, reference, relative difference, z).
void expect_regions_match_reference(const Rendered& render, const Image& reference, const std::vector<ImageRegion>& regions,
                                    double allowance, double family_alpha);

}  // namespace pathspace::testing
