// The pixel (reconstruction) filter of the film: box, tent, gaussian or mitchell, separable, with a
// support of [-radius, radius] pixels around a pixel's centre on each axis (pbrt-v4's and Mitsuba 3's
// definitions: the gaussian minus its value at the radius, Mitchell-Netravali with B and C).
//
// Both sides of the film use the same filter, so that every integrator estimates the same image:
//  * camera paths sample their raster offset from the filter (filter importance sampling), so each
//    path still adds to its own pixel with weight 1 (sample_filter_offset);
//  * light paths (LT, BPT's t = 1, PCLT's projections) splat to every pixel whose support holds the
//    point, weighted by the normalised filter (for_each_filter_pixel).
// Weight 1 on the camera side needs a filter that is never negative: Mitchell's negative lobes are
// dropped (the positive part, renormalised), with a warning where a scene asks for one.
//
// The filter is its tabulation: kBins steps of constant value over [0, radius] (the profile at each
// step's midpoint), sampled exactly by inversion and evaluated by the same steps. The unit box (the
// default, radius 0.5) takes neither table: its offsets are the raw uniform numbers, as before
// filters existed, so box images are unchanged.
#pragma once

#include <cstdint>

#include "pathspace/math/scalar.h"
#include "pathspace/sampling/warps.h"

namespace pathspace {

enum class PixelFilterKind : uint8_t { box, tent, gaussian, mitchell };

struct PixelFilter {
  static constexpr int kBins = 32;

  PixelFilterKind kind = PixelFilterKind::box;
  float radius = 0.5f;          // support half-width in pixels, each axis
  float sigma = 0.5f;           // gaussian standard deviation (pixels)
  float b = 1.f / 3.f, c = 1.f / 3.f;  // mitchell
  float value[kBins] = {};      // normalised 1D filter per step: sum(value) * step * 2 = 1
  float cdf[kBins + 1] = {};    // of |x| over [0, radius] in steps; cdf[kBins] = 1

  PS_HD bool is_unit_box() const { return kind == PixelFilterKind::box && radius == 0.5f; }
  PS_HD float step() const { return radius / float(kBins); }

  // The normalised 1D filter at offset x (pixels): integrates to 1 over [-radius, radius].
  PS_HD float eval_1d(float x) const {
    const float a = fabsf(x);
    if (!(a < radius)) return 0.f;
    if (is_unit_box()) return 1.f;
    const int i = int(a / step());
    return value[i < kBins ? i : kBins - 1];
  }
};

// The offset from the pixel centre (pixels, in [-radius, radius]) of a camera path's raster position
// on one axis for a uniform u in [0, 1): its density is eval_1d. Monotonic in u (stratification holds).
PS_INLINE float sample_filter_offset(const PixelFilter& f, float u) {
  const float t = fabsf(2.f * u - 1.f);  // |x| by inversion; the sign from the half u lies in
  int lo = 0, hi = PixelFilter::kBins;   // the step i with cdf[i] <= t < cdf[i + 1]
  while (hi - lo > 1) {
    const int mid = (lo + hi) / 2;
    if (f.cdf[mid] <= t) lo = mid; else hi = mid;
  }
  const float width = f.cdf[lo + 1] - f.cdf[lo];
  const float within = width > 0.f ? fminf((t - f.cdf[lo]) / width, 1.f) : 0.5f;
  const float a = (float(lo) + within) * f.step();
  return u < 0.5f ? -a : a;
}

// The raster position of a camera path through pixel (px, py) for uniform (ux, uy).
PS_INLINE Point2 sample_filter_raster(const PixelFilter& f, uint32_t px, uint32_t py, float ux, float uy) {
  if (f.is_unit_box()) return {float(px) + ux, float(py) + uy};  // bit-identical to the box of old
  return {float(px) + 0.5f + sample_filter_offset(f, ux), float(py) + 0.5f + sample_filter_offset(f, uy)};
}

// The pixel (i + j * width) that raster point (rx, ry) falls in; false outside the image.
PS_INLINE bool raster_pixel(int width, int height, float rx, float ry, uint32_t* pixel) {
  if (!(rx >= 0.f && rx < float(width) && ry >= 0.f && ry < float(height))) return false;
  const int i = min_int(int(rx), width - 1), j = min_int(int(ry), height - 1);
  *pixel = uint32_t(i) + uint32_t(j) * uint32_t(width);
  return true;
}

// Whether a point at raster (rx, ry) reaches any pixel of a width x height image.
PS_INLINE bool filter_reaches_image(const PixelFilter& f, int width, int height, float rx, float ry) {
  uint32_t pixel;
  if (f.is_unit_box()) return raster_pixel(width, height, rx, ry, &pixel);
  const float r = f.radius;
  return rx > -r && rx < float(width) + r && ry > -r && ry < float(height) + r;
}

// Calls add(pixel, weight) for every pixel whose filter support holds raster point (rx, ry), with
// the normalised filter's weight (a splat of value v adds v * weight: one pixel area in total).
template <typename Add>
PS_HD void for_each_filter_pixel(const PixelFilter& f, int width, int height, float rx, float ry, Add&& add) {
  if (f.is_unit_box()) {
    uint32_t pixel;
    if (raster_pixel(width, height, rx, ry, &pixel)) add(pixel, 1.f);
    return;
  }
  const float r = f.radius;
  // Pixel centres (i + 0.5) strictly within r of the point.
  const int i0 = max_int(0, int(ceilf(rx - r - 0.5f))), i1 = min_int(width - 1, int(floorf(rx + r - 0.5f)));
  const int j0 = max_int(0, int(ceilf(ry - r - 0.5f))), j1 = min_int(height - 1, int(floorf(ry + r - 0.5f)));
  for (int j = j0; j <= j1; ++j) {
    const float wy = f.eval_1d(float(j) + 0.5f - ry);
    if (!(wy > 0.f)) continue;
    for (int i = i0; i <= i1; ++i) {
      const float wx = f.eval_1d(float(i) + 0.5f - rx);
      if (wx > 0.f) add(uint32_t(i) + uint32_t(j) * uint32_t(width), wx * wy);
    }
  }
}

// Prefetches the one pixel a unit-box splat at (rx, ry) adds to (a film with width, height and
// prefetch(pixel): SplatFilmView); wider filters spread over several and prefetch nothing.
template <typename Film>
PS_HD void prefetch_filter_splat(const Film& film, const PixelFilter& f, float rx, float ry) {
  uint32_t pixel;
  if (f.is_unit_box() && raster_pixel(film.width, film.height, rx, ry, &pixel)) film.prefetch(pixel);
}

}  // namespace pathspace
