// Environment images from files (EXR, PFM, HDR and what else io/image_io reads; float files are
// linear, 8-bit files sRGB-decoded) for the scene loaders, plus pbrt-v4's "illuminance"
// normalisation. Read errors are image_io's pathspace::Error naming the file.
#pragma once

#include <string>

#include "pathspace/scene/environment_image.h"

namespace pathspace {

// The image at `path` as an environment with the given mapping; axis_* are the map's local x, y, z
// axes in world space (the loader's light-to-world transform applied to the unit vectors).
EnvironmentImage read_environment_image(const std::string& path, EnvironmentMapping mapping, const Vec3& axis_x,
                                        const Vec3& axis_y, const Vec3& axis_z);

// pbrt-v4's k_e for "illuminance" E_v (scale *= E_v / k_e): the luminance-weighted sum of
// cos(theta) over the local upper hemisphere (z > 0) times 2 pi / texel count, exactly as pbrt-v4
// computes it for its equal-area maps (that is half the map's physical illuminance, so pbrt-v4 maps
// end up with 2 E_v; kept for agreement with pbrt-v4). Lat-long maps (z-up, see pbrt_environment)
// use the same quantity: half their physical upper-hemisphere illuminance.
double pbrt_map_illuminance(const EnvironmentImage& image);

}  // namespace pathspace
