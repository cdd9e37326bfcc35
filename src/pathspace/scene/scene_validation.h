// The one check of a scene's values before it is rendered, whatever made it (built-in scene, pbrt,
// Mitsuba, glTF, OBJ, PLY, command-line camera changes). It keeps every number inside the range the
// float arithmetic and Embree handle (Embree aborts on ray origins beyond about 1.8e18, and squared
// triangle edges overflow float far earlier), and rejects physically meaningless materials and
// lights instead of rendering a silently wrong image. The rule, documented in docs/cli.md
// ("Scene values"): not finite, out of range or negative where only >= 0 makes sense is an error;
// reflectance above 1 (energy gain) and a scene without lights (a black image) are warnings.
#pragma once

#include <string>
#include <vector>

#include "pathspace/scene/scene.h"

namespace pathspace {

// Largest |coordinate| of any vertex, sphere centre, light or camera position, and largest sphere
// radius, lens radius and focus distance, in scene units.
inline constexpr float kMaxSceneCoordinate = 1e9f;
// Largest image width or height (pixels), for -r and for cameras from scene files alike.
inline constexpr int kMaxImageSide = 16384;
// Largest samples per pixel, for -s and for a scene file's own count (pbrt pixelsamples, Mitsuba
// sample_count) alike.
inline constexpr int kMaxSamplesPerPixel = 1 << 24;

// Throws pathspace::Error for the first value out of its range (naming the element and the value);
// appends warnings (one per kind) to *warnings.
void validate_scene(const Scene& scene, std::vector<std::string>* warnings);

}  // namespace pathspace
