// Image textures as kernels see them: linear RGB texels (row 0 at the top) behind a raw pointer,
// looked up with bilinear filtering (or nearest texel, for patterns with hard edges such as pbrt's
// checkerboard) and repeat, mirror or clamp addressing after a uv scale and offset.
// v = 0 is the bottom row of the image (the pbrt and OBJ convention; images are stored top first).
#pragma once

#include <cstddef>
#include <cstdint>

#include "pathspace/math/rgb.h"
#include "pathspace/sampling/warps.h"

namespace pathspace {

// What a lookup does outside [0, 1)^2 (Mitsuba's wrap_mode, pbrt-v4's wrap "repeat" and "clamp"):
// every texel index a lookup reads, the bilinear neighbours included, is wrapped this way, as
// Mitsuba and pbrt-v4 do.
enum class TextureWrap : uint8_t { repeat, mirror, clamp };

struct TextureView {
  const Rgb* texels = nullptr;  // width * height, row-major
  int32_t width = 0, height = 0;
  float uscale = 1.f, vscale = 1.f;  // pbrt's uscale / vscale
  float udelta = 0.f, vdelta = 0.f;  // pbrt's udelta / vdelta
  bool nearest = false;              // nearest texel instead of bilinear
  TextureWrap wrap = TextureWrap::repeat;
  // An 8-bit texture (scene/image_texture.h): 3 bytes a texel and each byte's linear value, used
  // instead of `texels` when set.
  const uint8_t* bytes = nullptr;
  const float* byte_values = nullptr;
};

namespace texture_detail {
// Fractional part in [0, 1); non-finite or huge coordinates map to 0 so the integer casts below
// stay defined.
PS_INLINE float wrap_unit(float s) {
  if (!(fabsf(s) < 1e7f)) return 0.f;
  const float f = s - floorf(s);
  return f < 1.f ? f : 0.f;
}
// The coordinate reduced to one period of the wrap mode, so that texel indices stay small: [0, 1)
// for repeat, [0, 2) for mirror (a period is the image and its mirror image), [-1, 2] for clamp.
PS_INLINE float reduce(float s, TextureWrap wrap) {
  if (wrap == TextureWrap::repeat) return wrap_unit(s);
  if (wrap == TextureWrap::mirror) return 2.f * wrap_unit(0.5f * s);
  return fabsf(s) < 1e7f ? fminf(fmaxf(s, -1.f), 2.f) : 0.f;
}
// Texel index i of a row or column of n texels, wrapped (i within a few periods of [0, n)).
PS_INLINE int wrap_index(int i, int n, TextureWrap wrap) {
  if (wrap == TextureWrap::clamp) return i < 0 ? 0 : (i >= n ? n - 1 : i);
  const int period = wrap == TextureWrap::mirror ? 2 * n : n;
  int m = i % period;
  if (m < 0) m += period;
  return m < n ? m : period - 1 - m;
}
}  // namespace texture_detail

PS_INLINE Rgb texture_texel(const TextureView& t, int x, int y) {
  const size_t i = size_t(y) * size_t(t.width) + size_t(x);
  if (t.bytes) {
    const uint8_t* b = t.bytes + 3 * i;
    return Rgb(t.byte_values[b[0]], t.byte_values[b[1]], t.byte_values[b[2]]);
  }
  return t.texels[i];
}

// Bilinear lookup: texel (i, j) has its centre at ((i + 0.5) / width, 1 - (j + 0.5) / height).
PS_INLINE Rgb texture_lookup(const TextureView& t, Point2 uv) {
  using texture_detail::reduce;
  using texture_detail::wrap_index;
  const float s = reduce(uv.x * t.uscale + t.udelta, t.wrap);
  const float r = reduce(uv.y * t.vscale + t.vdelta, t.wrap);
  if (t.nearest) {
    const int xn = int(floorf(s * float(t.width))), yn = int(floorf((1.f - r) * float(t.height)));
    if (t.wrap == TextureWrap::repeat)  // s, r in [0, 1): an index of `size` is rounding, kept at the last texel
      return texture_texel(t, xn < t.width ? xn : t.width - 1, yn < t.height ? yn : t.height - 1);
    return texture_texel(t, wrap_index(xn, t.width, t.wrap), wrap_index(yn, t.height, t.wrap));
  }
  const float x = s * float(t.width) - 0.5f, y = (1.f - r) * float(t.height) - 0.5f;
  const float fx = floorf(x), fy = floorf(y);
  const float ax = x - fx, ay = y - fy;
  const int x0 = wrap_index(int(fx), t.width, t.wrap), y0 = wrap_index(int(fy), t.height, t.wrap);
  const int x1 = wrap_index(int(fx) + 1, t.width, t.wrap), y1 = wrap_index(int(fy) + 1, t.height, t.wrap);
  const Rgb top = texture_texel(t, x0, y0) * (1.f - ax) + texture_texel(t, x1, y0) * ax;
  const Rgb bottom = texture_texel(t, x0, y1) * (1.f - ax) + texture_texel(t, x1, y1) * ax;
  return top * (1.f - ay) + bottom * ay;
}

}  // namespace pathspace
