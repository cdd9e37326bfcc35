// Spectra as scene files give them: wavelength (nm) / value pairs, linear in between and zero
// outside their range (pbrt-v4's piecewise-linear spectra), read from inline numbers or from .spd
// files; and Planck's blackbody law. spectrum_to_rgb.h turns them into the renderer's RGB.
#pragma once

#include <string>
#include <vector>

#include "pathspace/base/error.h"

namespace pathspace {

struct SampledSpectrum {
  std::vector<double> nm;     // strictly increasing
  std::vector<double> value;  // one per wavelength

  // Linear between samples; 0 outside [nm.front(), nm.back()].
  double at(double wavelength_nm) const;
};

// Interleaved pairs [nm0 v0 nm1 v1 ...], as pbrt-v4 writes them inline and in .spd files. Errors at
// `loc`: an odd count, no pair, a non-finite number or wavelengths that do not increase.
SampledSpectrum spectrum_from_pairs(const std::vector<double>& pairs, const FileLoc& loc, const std::string& what);

// An .spd file: whitespace-separated numbers, '#' to the end of a line is a comment, read as pairs.
// Errors carry the file's own line and column (a token that is not a number), or name the file.
SampledSpectrum read_spd_file(const std::string& path);

// Planck's law for a blackbody at `kelvin`, sampled every nanometre over the visible range, in one
// of two units: divided by its value at the peak wavelength (Wien's displacement law), as pbrt-v4's
// BlackbodySpectrum normalises it, or as spectral radiance in W / (m^2 sr nm), Mitsuba's unit.
// Throws Error at `loc` unless 1 <= kelvin <= 1e9.
enum class BlackbodyUnit { peak_normalised, radiance_per_nm };
SampledSpectrum blackbody_spectrum(double kelvin, BlackbodyUnit unit, const FileLoc& loc);

}  // namespace pathspace
