#include "pathspace/io/spectrum/sampled_spectrum.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>

#include "pathspace/io/file_bytes.h"
#include "pathspace/io/spectrum/cie_tables.h"

namespace pathspace {

double SampledSpectrum::at(double wavelength_nm) const {
  if (nm.empty() || !(wavelength_nm >= nm.front() && wavelength_nm <= nm.back())) return 0.0;
  const size_t i = size_t(std::upper_bound(nm.begin(), nm.end(), wavelength_nm) - nm.begin());
  if (i >= nm.size()) return value.back();
  const double t = (wavelength_nm - nm[i - 1]) / (nm[i] - nm[i - 1]);
  return value[i - 1] + (value[i] - value[i - 1]) * t;
}

SampledSpectrum spectrum_from_pairs(const std::vector<double>& pairs, const FileLoc& loc, const std::string& what) {
  if (pairs.size() < 2 || pairs.size() % 2 != 0)
    throw Error(loc, what + " needs wavelength/value pairs (got " + std::to_string(pairs.size()) + " numbers)");
  SampledSpectrum s;
  for (size_t i = 0; i < pairs.size(); i += 2) {
    if (!std::isfinite(pairs[i]) || !std::isfinite(pairs[i + 1])) throw Error(loc, what + " holds a non-finite number");
    if (!s.nm.empty() && !(pairs[i] > s.nm.back()))
      throw Error(loc, what + ": wavelengths must increase (" + std::to_string(pairs[i]) + " nm after " +
                           std::to_string(s.nm.back()) + " nm)");
    s.nm.push_back(pairs[i]);
    s.value.push_back(pairs[i + 1]);
  }
  return s;
}

SampledSpectrum read_spd_file(const std::string& path) {
  const std::string text = read_file_bytes(path);
  std::vector<double> numbers;
  int line = 1;
  size_t line_start = 0;
  size_t i = 0;
  while (i < text.size()) {
    const char c = text[i];
    if (c == '\n') {
      ++line;
      line_start = ++i;
    } else if (c == ' ' || c == '\t' || c == '\r' || c == ',') {
      ++i;
    } else if (c == '#') {
      while (i < text.size() && text[i] != '\n') ++i;
    } else {
      size_t end = i;
      while (end < text.size() && !std::isspace(static_cast<unsigned char>(text[end])) && text[end] != ',' && text[end] != '#') ++end;
      const std::string token = text.substr(i, end - i);
      char* stop = nullptr;
      errno = 0;
      const double v = std::strtod(token.c_str(), &stop);
      const FileLoc at{path, line, int(i - line_start) + 1};
      if (stop != token.c_str() + token.size() || token.empty()) throw Error(at, "expected a number, found '" + token + "'");
      if (errno == ERANGE || !std::isfinite(v)) throw Error(at, "number '" + token + "' is out of range");
      numbers.push_back(v);
      i = end;
    }
  }
  return spectrum_from_pairs(numbers, FileLoc{path, 0, 0}, "spectrum file");
}

SampledSpectrum blackbody_spectrum(double kelvin, BlackbodyUnit unit, const FileLoc& loc) {
  // Far outside this range the spectrum underflows to zero or the peak leaves double's range.
  if (!(kelvin >= 1.0 && kelvin <= 1e9)) throw Error(loc, "blackbody temperature must be between 1 and 1e9 kelvin");
  // Planck's law, spectral radiance per metre of wavelength; constants as CODATA 2018 gives them.
  constexpr double h = 6.62607015e-34, c = 299792458.0, kb = 1.380649e-23;
  auto planck = [&](double nm) {
    const double l = nm * 1e-9;
    return 2.0 * h * c * c / (std::pow(l, 5) * std::expm1(h * c / (l * kb * kelvin)));
  };
  const double peak_nm = 2.897771955e-3 / kelvin * 1e9;  // Wien's displacement constant b / T
  const double peak = unit == BlackbodyUnit::peak_normalised ? planck(peak_nm) : 1e9;  // per metre -> per nm
  SampledSpectrum s;
  for (double nm = kCieFirstNm; nm <= kCieLastNm; nm += 1.0) {
    s.nm.push_back(nm);
    s.value.push_back(planck(nm) / peak);
  }
  return s;
}

}  // namespace pathspace
