// Named spectra shared by the scene loaders: RGB fits of measured metal IORs (pbrt's
// "metal-Cu-eta", Mitsuba's conductor material "Cu") and refractive indices of glasses and other
// dielectrics (pbrt's "glass-BK7", Mitsuba's int_ior="bk7"), so both formats agree on one table.
#pragma once

#include <string_view>

#include "pathspace/math/rgb.h"

namespace pathspace {

// pbrt-style spectrum names ("metal-Au-k", "glass-F5"); false when the name is not in the table.
bool find_named_spectrum(std::string_view name, Rgb* value);

// Mitsuba's named refractive indices ("bk7", "water", "air", ...); false when unknown.
bool find_named_ior(std::string_view name, float* ior);

}  // namespace pathspace
