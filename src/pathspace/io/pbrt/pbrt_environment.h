// pbrt-v4 `LightSource "infinite" "string filename"`: the image and its light-to-world frame (the
// CTM at the light). Square images use pbrt-v4's equal-area octahedral mapping (local z up, nearest
// texel, as its ImageInfiniteLight). pbrt-v4 rejects other shapes; they are read as pbrt-v3 lat-long
// maps instead (local z up, phi = 2 pi u from +x towards +y, theta = pi v from +z, v = 0 the top row)
// with a warning, which is what scenes converted from pbrt-v3 / Tungsten need.
#pragma once

#include <string>

#include "pathspace/io/load_warnings.h"
#include "pathspace/io/pbrt/pbrt_transform.h"
#include "pathspace/scene/environment_image.h"

namespace pathspace::pbrt {

EnvironmentImage read_pbrt_environment(const std::string& path, const Mat4& light_to_world, const FileLoc& loc,
                                       LoadWarnings* warnings);

}  // namespace pathspace::pbrt
