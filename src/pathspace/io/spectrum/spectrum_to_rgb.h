// Spectra into the renderer's colour space, linear sRGB (D65 white). How depends on what the
// spectrum describes (docs/conventions.md, "Spectra"):
//  - reflectance: the surface's colour under D65 relative to D65's white, so a constant
//    spectrum c gives (c, c, c);
//  - unbounded (complex IORs and other non-reflectance quantities): XYZ divided by the integral of
//    y-bar, to sRGB. It is the convention of Mitsuba's and Tungsten's RGB metal tables, which
//    named_spectra.h holds: pbrt-v4's measured gold, copper, silver and aluminium give those
//    tables' values to 0.3%;
//  - illuminant: the emitter's colour at luminance Y = 1. pbrt-v4 divides every light's spectrum
//    by its luminance (SpectrumToPhotometric) and lets "scale" or "power" set the magnitude.
#pragma once

#include "pathspace/io/spectrum/sampled_spectrum.h"
#include "pathspace/math/rgb.h"

namespace pathspace {

enum class SpectrumUse { reflectance, unbounded, illuminant };

// Integrated every nanometre over CIE 1931's range. An illuminant without visible power is black.
Rgb spectrum_to_rgb(const SampledSpectrum& s, SpectrumUse use);

// The spectrum's mean weighted by y-bar, the Y of the unbounded conversion: one number for a
// quantity the renderer keeps as a scalar (a dielectric's index of refraction).
double y_bar_weighted_mean(const SampledSpectrum& s);

// CIE XYZ to linear sRGB (IEC 61966-2-1's matrix, D65 white).
Rgb xyz_to_linear_srgb(double x, double y, double z);

}  // namespace pathspace
