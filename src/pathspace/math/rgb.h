// Linear sRGB colour triple (radiance, reflectance, throughput). Never gamma-encoded:
// encoding happens only when writing PNG (film/tonemap.h).
#pragma once

#include "pathspace/math/scalar.h"

namespace pathspace {

struct Rgb {
  float r = 0.f, g = 0.f, b = 0.f;

  constexpr Rgb() = default;
  PS_HD constexpr Rgb(float r_, float g_, float b_) : r(r_), g(g_), b(b_) {}
  PS_HD constexpr explicit Rgb(float s) : r(s), g(s), b(s) {}

  PS_HD float operator[](int i) const { return i == 0 ? r : (i == 1 ? g : b); }
  PS_HD float& operator[](int i) { return i == 0 ? r : (i == 1 ? g : b); }
  PS_HD Rgb& operator+=(const Rgb& o) { r += o.r; g += o.g; b += o.b; return *this; }
  PS_HD Rgb& operator*=(const Rgb& o) { r *= o.r; g *= o.g; b *= o.b; return *this; }
  PS_HD Rgb& operator*=(float s) { r *= s; g *= s; b *= s; return *this; }
};

PS_INLINE Rgb operator+(const Rgb& a, const Rgb& b) { return {a.r + b.r, a.g + b.g, a.b + b.b}; }
PS_INLINE Rgb operator-(const Rgb& a, const Rgb& b) { return {a.r - b.r, a.g - b.g, a.b - b.b}; }
PS_INLINE Rgb operator*(const Rgb& a, const Rgb& b) { return {a.r * b.r, a.g * b.g, a.b * b.b}; }
PS_INLINE Rgb operator*(const Rgb& a, float s) { return {a.r * s, a.g * s, a.b * s}; }
PS_INLINE Rgb operator*(float s, const Rgb& a) { return a * s; }
PS_INLINE Rgb operator/(const Rgb& a, float s) { return a * (1.f / s); }
PS_INLINE bool operator==(const Rgb& a, const Rgb& b) { return a.r == b.r && a.g == b.g && a.b == b.b; }

PS_INLINE bool is_black(const Rgb& c) { return c.r == 0.f && c.g == 0.f && c.b == 0.f; }
PS_INLINE float max_component(const Rgb& c) { return fmaxf(c.r, fmaxf(c.g, c.b)); }
PS_INLINE float average(const Rgb& c) { return (c.r + c.g + c.b) * (1.f / 3.f); }
// Rec. 709 / linear sRGB luminance (the weights of docs/conventions.md and SmallVCM), in float or
// in double (the hashed filter's fixed-point sums).
template <typename T>
PS_INLINE T luminance_of(T r, T g, T b) { return T(0.212671) * r + T(0.715160) * g + T(0.072169) * b; }
PS_INLINE float luminance(const Rgb& c) { return luminance_of(c.r, c.g, c.b); }
static_assert(float(0.212671) == 0.212671f && float(0.715160) == 0.715160f && float(0.072169) == 0.072169f,
              "the float weights are the decimal constants rounded once");
PS_INLINE bool all_finite(const Rgb& c) { return isfinite(c.r) && isfinite(c.g) && isfinite(c.b); }

}  // namespace pathspace
