#include "pathspace/film/image_metrics.h"

#include <string>

#include "pathspace/base/error.h"

namespace pathspace {

void check_same_size(const Image& a, const Image& b) {
  if (a.width != b.width || a.height != b.height)
    throw Error("image sizes differ: " + std::to_string(a.width) + "x" + std::to_string(a.height) + " vs " +
                std::to_string(b.width) + "x" + std::to_string(b.height));
}

ImageError image_error(const Image& image, const Image& reference, const Image* reference_variance, double epsilon) {
  check_same_size(image, reference);
  if (reference_variance) check_same_size(image, *reference_variance);
  ImageError e;
  const double n = 3.0 * double(image.size());
  for (size_t i = 0; i < image.size(); ++i) {
    for (int c = 0; c < 3; ++c) {
      const double x = image.pixels[i][c], r = reference.pixels[i][c];
      double sq = (x - r) * (x - r);
      if (reference_variance) sq -= reference_variance->pixels[i][c];  // E[(x - R)^2] = MSE + Var(R)
      e.mse += sq;
      e.rel_mse += sq / (r * r + epsilon);
      e.mean_image += x;
      e.mean_reference += r;
    }
  }
  e.mse /= n;
  e.rel_mse /= n;
  e.mean_image /= n;
  e.mean_reference /= n;
  return e;
}

Image rel_error_map(const Image& image, const Image& reference, double epsilon) {
  check_same_size(image, reference);
  Image map(image.width, image.height);
  for (size_t i = 0; i < image.size(); ++i) {
    double s = 0.0;
    for (int c = 0; c < 3; ++c) {
      const double d = double(image.pixels[i][c]) - double(reference.pixels[i][c]);
      s += d * d / (double(reference.pixels[i][c]) * double(reference.pixels[i][c]) + epsilon);
    }
    map.pixels[i] = Rgb(float(s / 3.0));
  }
  return map;
}

}  // namespace pathspace
