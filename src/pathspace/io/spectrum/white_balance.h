// pbrt-v4's film white balance (its PixelSensor with the cie1931 sensor and "whitebalance" T):
// a von Kries adaptation in the Bradford cone space from the white of CIE daylight D_T to the colour
// space's white, D65. As a matrix on linear sRGB (the renderer's colour space) it maps the colour of
// D_T to (1, 1, 1) times D_T's luminance.
#pragma once

#include <array>

namespace pathspace {

// CIE xy of CIE daylight at a correlated colour temperature (CIE 015: x_D as a cubic in 1/T for
// 4000-7000 K and 7000-25000 K, y_D = -3 x_D^2 + 2.870 x_D - 0.275). Throws Error outside 4000-25000 K.
std::array<double, 2> daylight_chromaticity(double kelvin);

// Row-major 3x3 on linear sRGB; identity for kelvin == 0 (no white balance).
std::array<float, 9> white_balance_matrix(double kelvin);

}  // namespace pathspace
