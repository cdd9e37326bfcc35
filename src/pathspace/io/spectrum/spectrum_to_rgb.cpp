#include "pathspace/io/spectrum/spectrum_to_rgb.h"

#include "pathspace/io/spectrum/cie_tables.h"

namespace pathspace {

Rgb xyz_to_linear_srgb(double x, double y, double z) {
  return Rgb(float(3.2404542 * x - 1.5371385 * y - 0.4985314 * z), float(-0.9692660 * x + 1.8760108 * y + 0.0415560 * z),
             float(0.0556434 * x - 0.2040259 * y + 1.0572252 * z));
}

Rgb spectrum_to_rgb(const SampledSpectrum& s, SpectrumUse use) {
  double x = 0, y = 0, z = 0, norm = 0;
  for (double nm = kCieFirstNm; nm <= kCieLastNm; nm += 1.0) {
    const CieSample c = cie_at(nm);
    double v = s.at(nm);
    if (use == SpectrumUse::reflectance) v *= c.d65;
    x += v * c.x;
    y += v * c.y;
    z += v * c.z;
    norm += use == SpectrumUse::reflectance ? c.d65 * c.y : use == SpectrumUse::unbounded ? c.y : v * c.y;
  }
  if (!(norm > 0.0)) return Rgb(0.f);
  return xyz_to_linear_srgb(x / norm, y / norm, z / norm);
}

double y_bar_weighted_mean(const SampledSpectrum& s) {
  double y = 0, norm = 0;
  for (double nm = kCieFirstNm; nm <= kCieLastNm; nm += 1.0) {
    const CieSample c = cie_at(nm);
    y += s.at(nm) * c.y;
    norm += c.y;
  }
  return y / norm;
}

}  // namespace pathspace
