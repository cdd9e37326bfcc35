// A linear RGB float image, row-major, row 0 at the top (raster convention).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "pathspace/math/rgb.h"

namespace pathspace {

struct Image {
  int width = 0, height = 0;
  std::vector<Rgb> pixels;

  Image() = default;
  Image(int w, int h) : width(w), height(h), pixels(size_t(w) * size_t(h)) {}
  Rgb& at(int x, int y) { return pixels[size_t(y) * size_t(width) + size_t(x)]; }
  const Rgb& at(int x, int y) const { return pixels[size_t(y) * size_t(width) + size_t(x)]; }
  size_t size() const { return pixels.size(); }
};

// A named image besides the render itself: an integrator's or filter's debug image (AOV), e.g. the
// hashed filter's voxel ids or BPT's per-strategy images.
struct NamedImage {
  std::string name;
  Image image;
};

}  // namespace pathspace
