// CIE colorimetry data for turning spectra into RGB (spectrum_to_rgb.h): the CIE 1931 colour
// matching functions and standard illuminant D65, interpolated linearly between 5 nm samples.
#pragma once

namespace pathspace {

inline constexpr double kCieFirstNm = 360.0;
inline constexpr double kCieLastNm = 830.0;
inline constexpr double kCieStepNm = 5.0;

// The colour matching functions and D65's relative power (100 at 560 nm) at one wavelength; all
// zero outside [kCieFirstNm, kCieLastNm].
struct CieSample {
  double x = 0, y = 0, z = 0, d65 = 0;
};
CieSample cie_at(double nm);

// CIE standard illuminant A's relative power (100 at 560 nm), from its defining formula (CIE 015):
// Planck's law at 2856 K, written with the second radiation constant of 1931 (1.435e-2 m K), which
// puts 2848 K into the formula.
double cie_illuminant_a(double nm);

}  // namespace pathspace
