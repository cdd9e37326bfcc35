#include "pathspace/io/spectrum/white_balance.h"

#include <string>

#include "pathspace/base/error.h"

namespace pathspace {

namespace {

using Mat3 = std::array<double, 9>;

Mat3 multiply(const Mat3& a, const Mat3& b) {
  Mat3 c{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) c[3 * i + j] += a[3 * i + k] * b[3 * k + j];
  return c;
}

std::array<double, 3> apply(const Mat3& m, const std::array<double, 3>& v) {
  return {m[0] * v[0] + m[1] * v[1] + m[2] * v[2], m[3] * v[0] + m[4] * v[1] + m[5] * v[2],
          m[6] * v[0] + m[7] * v[1] + m[8] * v[2]};
}

std::array<double, 3> xyz_of_chromaticity(double x, double y) { return {x / y, 1.0, (1.0 - x - y) / y}; }

// IEC 61966-2-1's sRGB matrices (D65) and the Bradford cone response.
constexpr Mat3 kXyzFromSrgb = {0.4124564, 0.3575761, 0.1804375, 0.2126729, 0.7151522, 0.0721750, 0.0193339, 0.1191920, 0.9503041};
constexpr Mat3 kSrgbFromXyz = {3.2404542, -1.5371385, -0.4985314, -0.9692660, 1.8760108, 0.0415560, 0.0556434, -0.2040259, 1.0572252};
constexpr Mat3 kLmsFromXyz = {0.8951, 0.2664, -0.1614, -0.7502, 1.7135, 0.0367, 0.0389, -0.0685, 1.0296};
constexpr Mat3 kXyzFromLms = {0.9869929, -0.1470543, 0.1599627, 0.4323053, 0.5183603, 0.0492912, -0.0085287, 0.0400428, 0.9684867};
constexpr double kD65x = 0.3127, kD65y = 0.3290;

}  // namespace

std::array<double, 2> daylight_chromaticity(double t) {
  if (!(t >= 4000.0 && t <= 25000.0))
    throw Error("white balance temperature " + std::to_string(t) + " K is outside CIE daylight's 4000-25000 K");
  const double x = t <= 7000.0 ? -4.6070e9 / (t * t * t) + 2.9678e6 / (t * t) + 0.09911e3 / t + 0.244063
                               : -2.0064e9 / (t * t * t) + 1.9018e6 / (t * t) + 0.24748e3 / t + 0.237040;
  return {x, -3.0 * x * x + 2.870 * x - 0.275};
}

std::array<float, 9> white_balance_matrix(double kelvin) {
  if (kelvin == 0.0) return {1, 0, 0, 0, 1, 0, 0, 0, 1};
  const std::array<double, 2> source = daylight_chromaticity(kelvin);
  const std::array<double, 3> from = apply(kLmsFromXyz, xyz_of_chromaticity(source[0], source[1]));
  const std::array<double, 3> to = apply(kLmsFromXyz, xyz_of_chromaticity(kD65x, kD65y));
  const Mat3 scale = {to[0] / from[0], 0, 0, 0, to[1] / from[1], 0, 0, 0, to[2] / from[2]};
  const Mat3 m = multiply(kSrgbFromXyz, multiply(kXyzFromLms, multiply(scale, multiply(kLmsFromXyz, kXyzFromSrgb))));
  std::array<float, 9> out{};
  for (int i = 0; i < 9; ++i) out[i] = float(m[i]);
  return out;
}

}  // namespace pathspace
