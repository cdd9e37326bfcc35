// False-colour error maps of the experiments (the error images next to the renders, e.g. of the PCLT
// paper's figs. 1 and 5-8): per-pixel relative squared error on a fixed logarithmic scale, so maps
// of different runs and scenes can be compared by eye. The ramp is our own (black -> blue -> red ->
// yellow -> white), chosen to be monotonic in brightness so it also reads in greyscale.
#pragma once

#include <string>

#include "pathspace/film/image.h"

namespace pathspace::study {

// The scale: errors at or below kErrorMapLow are black, at or above kErrorMapHigh white, log10 between.
inline constexpr double kErrorMapLow = 1e-4;
inline constexpr double kErrorMapHigh = 1.0;

// sRGB-encoded colour (0..1 per channel) of t in [0, 1] (clamped; NaN maps to 0).
Rgb error_ramp_srgb(double t);

// Colours a per-pixel error image (channel 0 is read; rel_error_map writes grey) on the fixed scale.
// The result holds *linear* values whose sRGB encoding is the ramp colour, so writing it as PNG
// (film/tonemap.h) reproduces the ramp exactly.
Image colour_error_map(const Image& error);

// A CSS linear-gradient(...) of the ramp, left = kErrorMapLow, right = kErrorMapHigh (HTML legend).
std::string error_ramp_css_gradient();

}  // namespace pathspace::study
