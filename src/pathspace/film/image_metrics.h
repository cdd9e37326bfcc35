// Error metrics between an image and a reference (what the papers report): MSE and relMSE
// (per channel (I - R)^2 / (R^2 + eps), averaged), optionally debiased by the reference's own
// variance-of-the-mean image, so that a finite-sample reference does not inflate the error.
#pragma once

#include "pathspace/film/image.h"

namespace pathspace {

struct ImageError {
  double mse = 0.0;
  double rel_mse = 0.0;
  double mean_image = 0.0, mean_reference = 0.0;  // channel averages (bias check)
};

inline constexpr double kRelMseEpsilon = 1e-2;

// Throws pathspace::Error naming both sizes when a and b differ in size: the metrics' common check.
void check_same_size(const Image& a, const Image& b);

// Throws pathspace::Error when sizes differ. reference_variance may be null.
ImageError image_error(const Image& image, const Image& reference, const Image* reference_variance = nullptr,
                       double epsilon = kRelMseEpsilon);

// Per-pixel relative squared error (channel average), for error maps.
Image rel_error_map(const Image& image, const Image& reference, double epsilon = kRelMseEpsilon);

}  // namespace pathspace
