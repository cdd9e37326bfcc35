// A scene file's pixel filter (pbrt-v4 PixelFilter, Mitsuba 3 rfilter) as the camera's
// (camera/pixel_filter.h), shared by the loaders so both formats approximate alike.
#pragma once

#include "pathspace/base/error.h"
#include "pathspace/camera/pixel_filter.h"
#include "pathspace/io/load_warnings.h"

namespace pathspace {

// The filter of `kind` with the file's parameters (radius in pixels; sigma for the gaussian, B and C
// for Mitchell). Out-of-range values are an Error at `loc`; Mitchell's negative lobes are dropped
// with a warning (pixel_filter.h).
PixelFilter scene_pixel_filter(PixelFilterKind kind, double radius, double sigma, double b, double c, const FileLoc& loc,
                               LoadWarnings* warnings);

}  // namespace pathspace
