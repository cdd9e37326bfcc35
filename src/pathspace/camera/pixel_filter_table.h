// Building pixel filters (camera/pixel_filter.h) from their parameters, their names, and a one-line
// description for `info`.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "pathspace/camera/pixel_filter.h"

namespace pathspace {

// The names of the filter kinds, as the CLI and the scene formats write them.
const std::vector<std::pair<std::string, PixelFilterKind>>& pixel_filter_kinds();
std::vector<std::string> pixel_filter_names();
std::optional<PixelFilterKind> parse_pixel_filter_kind(const std::string& name);
const char* pixel_filter_name(PixelFilterKind kind);

// The kind's usual radius in pixels (pbrt-v4's defaults: box 0.5, tent 2, gaussian 1.5, mitchell 2).
float default_pixel_filter_radius(PixelFilterKind kind);

// A filter of `kind` with its table built. radius in (0, kMaxPixelFilterRadius]; sigma > 0 (gaussian);
// B, C finite (mitchell). Throws pathspace::Error otherwise.
inline constexpr float kMaxPixelFilterRadius = 16.f;
PixelFilter make_pixel_filter(PixelFilterKind kind, float radius, float sigma = 0.5f, float b = 1.f / 3.f, float c = 1.f / 3.f);

// "box 0.5", "gaussian 1.5 (sigma 0.5)", "mitchell 2 (B 0.333, C 0.333)".
std::string describe_pixel_filter(const PixelFilter& f);

}  // namespace pathspace
