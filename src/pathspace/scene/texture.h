// Image textures as kernels see them: linear RGB texels (row 0 at the top) behind a raw pointer,
// looked up with bilinear filtering (or nearest texel, for patterns with hard edges such as pbrt's
// checkerboard) and repeat (wrap) addressing after a uv scale and offset.
// v = 0 is the bottom row of the image (the pbrt and OBJ convention; images are stored top first).
#pragma once

#include <cstddef>
#include <cstdint>

#include "pathspace/math/rgb.h"
#include "pathspace/sampling/warps.h"

namespace pathspace {

struct TextureView {
  const Rgb* texels = nullptr;  // width * height, row-major
  int32_t width = 0, height = 0;
  float uscale = 1.f, vscale = 1.f;  // pbrt's uscale / vscale
  float udelta = 0.f, vdelta = 0.f;  // pbrt's udelta / vdelta
  bool nearest = false;              // nearest texel instead of bilinear
};

namespace texture_detail {
// Fractional part in [0, 1); non-finite or huge coordinates map to 0 so the integer casts below
// stay defined.
PS_INLINE float wrap_unit(float s) {
  if (!(fabsf(s) < 1e7f)) return 0.f;
  const float f = s - floorf(s);
  return f < 1.f ? f : 0.f;
}
}  // namespace texture_detail

PS_INLINE Rgb texture_texel(const TextureView& t, int x, int y) {
  return t.texels[size_t(y) * size_t(t.width) + size_t(x)];
}

// Bilinear lookup: texel (i, j) has its centre at ((i + 0.5) / width, 1 - (j + 0.5) / height).
PS_INLINE Rgb texture_lookup(const TextureView& t, Point2 uv) {
  using texture_detail::wrap_unit;
  const float s = wrap_unit(uv.x * t.uscale + t.udelta);
  const float r = wrap_unit(uv.y * t.vscale + t.vdelta);
  if (t.nearest) {
    const int xn = int(s * float(t.width)), yn = int((1.f - r) * float(t.height));
    return texture_texel(t, xn < t.width ? xn : t.width - 1, yn < t.height ? yn : t.height - 1);
  }
  const float x = s * float(t.width) - 0.5f, y = (1.f - r) * float(t.height) - 0.5f;
  const float fx = floorf(x), fy = floorf(y);
  const float ax = x - fx, ay = y - fy;
  int x0 = int(fx), y0 = int(fy);  // in [-1, size - 1]
  int x1 = x0 + 1, y1 = y0 + 1;    // in [0, size]
  if (x0 < 0) x0 += t.width;
  if (y0 < 0) y0 += t.height;
  if (x1 >= t.width) x1 -= t.width;
  if (y1 >= t.height) y1 -= t.height;
  const Rgb top = texture_texel(t, x0, y0) * (1.f - ax) + texture_texel(t, x1, y0) * ax;
  const Rgb bottom = texture_texel(t, x0, y1) * (1.f - ax) + texture_texel(t, x1, y1) * ax;
  return top * (1.f - ay) + bottom * ay;
}

}  // namespace pathspace
