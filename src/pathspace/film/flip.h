// FLIP for LDR images (Andersson, Nilsson, Akenine-Möller, Oskarsson, Åström, Fairchild: "FLIP: A
// Difference Evaluator for Alternating Images", HPG 2020): the difference a viewer sees when flipping
// between two images, per pixel in [0, 1]. Colour: CSF filtering in YCxCz (sec. 3.1), Hunt-adjusted
// HyAB in CIELab, remapped (eq. 2-3); features: edges and points of the achromatic channel (sec. 3.2);
// combined as colour^(1 - feature) (eq. 5). Written from the paper, in double precision.
#pragma once

#include "pathspace/film/image.h"

namespace pathspace {

// The paper's viewing condition: 0.7 m from a 0.7 m wide monitor of 3840 pixels, which is 67 pixels per
// degree of visual angle (distance · pixels / width · π / 180 = 67.02; the rounded value is the one the
// published example figures of tests/unit/flip_test.cpp use; the two give means 1e-5 apart).
inline constexpr double kFlipPixelsPerDegree = 67.0;

struct FlipResult {
  double mean = 0.0;  // mean FLIP over all pixels (the single number the authors recommend)
  Image map;          // per-pixel FLIP (grey), only when asked for; else empty
};

// test and reference are pathspace images (linear RGB); FLIP's LDR pipeline sees them clamped to
// [0, 1], i.e. as the sRGB display would show them. Symmetric in its two images. Throws
// pathspace::Error when the sizes differ or pixels_per_degree is not positive and finite.
FlipResult flip(const Image& test, const Image& reference, double pixels_per_degree = kFlipPixelsPerDegree,
                bool with_map = false);

}  // namespace pathspace
