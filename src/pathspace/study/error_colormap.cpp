// False-colour ramp and error map colouring of the experiments' error images (error_colormap.h).
#include "pathspace/study/error_colormap.h"

#include <algorithm>
#include <array>
#include <cmath>

#include <fmt/format.h>

#include "pathspace/film/tonemap.h"

namespace pathspace::study {

namespace {

struct Stop {
  double t;
  Rgb c;  // sRGB-encoded
};

// Brightness rises along the ramp, so "more error" is always "brighter" even without colour vision.
constexpr std::array<Stop, 5> kStops = {{
    {0.00, Rgb(0.00f, 0.00f, 0.00f)},
    {0.25, Rgb(0.10f, 0.15f, 0.65f)},
    {0.55, Rgb(0.85f, 0.15f, 0.20f)},
    {0.80, Rgb(1.00f, 0.80f, 0.10f)},
    {1.00, Rgb(1.00f, 1.00f, 1.00f)},
}};

}  // namespace

Rgb error_ramp_srgb(double t) {
  if (!(t > 0.0)) return kStops.front().c;  // also NaN
  if (t >= 1.0) return kStops.back().c;
  for (size_t i = 1; i < kStops.size(); ++i) {
    if (t > kStops[i].t) continue;
    const double u = (t - kStops[i - 1].t) / (kStops[i].t - kStops[i - 1].t);
    const Rgb& a = kStops[i - 1].c;
    const Rgb& b = kStops[i].c;
    return Rgb(float(a.r + (b.r - a.r) * u), float(a.g + (b.g - a.g) * u), float(a.b + (b.b - a.b) * u));
  }
  return kStops.back().c;
}

Image colour_error_map(const Image& error) {
  Image out(error.width, error.height);
  const double lo = std::log10(kErrorMapLow), hi = std::log10(kErrorMapHigh);
  for (size_t i = 0; i < error.size(); ++i) {
    const double e = error.pixels[i].r;
    const double t = e > 0.0 ? (std::log10(e) - lo) / (hi - lo) : 0.0;
    const Rgb s = error_ramp_srgb(std::isfinite(t) ? t : 1.0);  // an infinite error is maximal, not black
    out.pixels[i] = Rgb(linear_from_srgb(s.r), linear_from_srgb(s.g), linear_from_srgb(s.b));
  }
  return out;
}

std::string error_ramp_css_gradient() {
  std::string css = "linear-gradient(to right";
  for (const Stop& s : kStops)
    css += fmt::format(", rgb({},{},{}) {:.0f}%", int(std::lround(s.c.r * 255.f)), int(std::lround(s.c.g * 255.f)),
                       int(std::lround(s.c.b * 255.f)), s.t * 100.0);
  return css + ")";
}

}  // namespace pathspace::study
