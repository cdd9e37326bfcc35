// Edge-avoiding à-trous wavelet filter (Dammertz, Sewtz, Hanika, Lensch: "Edge-Avoiding À-Trous
// Wavelet Transform for fast Global Illumination Filtering", HPG 2010): the screen-space baseline
// that `pathspace study psf` puts beside path space filtering at equal time. Each iteration i
// convolves with the 5x5 B3-spline kernel (1/16, 1/4, 3/8, 1/4, 1/16 per axis) whose taps are
// 2^i pixels apart (the "holes"), each tap weighted by edge-stopping functions on colour (sec. 3,
// the colour sigma halved every iteration), normal, position and, as our addition, albedo (guide
// buffers of the first camera hits, guide_buffers.h). A study baseline, not a render feature.
#pragma once

#include "pathspace/film/image.h"
#include "studies/psf/guide_buffers.h"

namespace pathspace::study {

struct AtrousSettings {
  int iterations = 5;           // the paper's 5: taps up to 2 * 2^4 = 32 pixels away
  float sigma_colour = 1.0f;    // linear RGB; iteration i uses sigma_colour * 2^-i (paper, sec. 3)
  float sigma_normal = 0.3f;    // on |n_p - n_q|
  float sigma_position = 1.0f;  // on |x_p - x_q| / (footprint_p * tap distance in pixels): 1 on a plane facing the camera
  float sigma_albedo = 0.1f;    // on |a_p - a_q| per RGB channel vector
};

// Filters `colour` (the guide's size). Pixels whose ray missed mix only with each other. Throws
// pathspace::Error when the sizes differ or the settings are not positive.
Image atrous_filter(const Image& colour, const GuideBuffers& guide, const AtrousSettings& settings = {});

}  // namespace pathspace::study
