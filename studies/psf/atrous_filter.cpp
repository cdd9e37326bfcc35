// The à-trous iterations (atrous_filter.h). Weights are exp(-d^2 / sigma^2) per guide, as in the
// paper's eqs. for w_rt, w_n and w_x; the normalisation divides by the sum of h * w, so a constant
// image stays constant whatever the guides.
#include "studies/psf/atrous_filter.h"

#include <cmath>

#include <fmt/format.h>

#include "pathspace/base/error.h"
#include "pathspace/parallel/parallel_for.h"

namespace pathspace::study {

namespace {

constexpr float kB3[5] = {1.f / 16.f, 1.f / 4.f, 3.f / 8.f, 1.f / 4.f, 1.f / 16.f};

float squared(const Rgb& c) { return c.r * c.r + c.g * c.g + c.b * c.b; }

struct Sigmas {
  float inv_colour2, inv_normal2, inv_position2, inv_albedo2;
};

void iterate(const Image& in, const GuideBuffers& g, int step, const Sigmas& s, Image* out) {
  const int w = in.width, h = in.height;
  parallel_for(size_t(h), 1, [&](size_t row_begin, size_t row_end) {
    for (size_t row = row_begin; row < row_end; ++row) {
      for (int x = 0; x < w; ++x) {
        const int y = int(row);
        const size_t p = size_t(y) * size_t(w) + size_t(x);
        const Rgb cp = in.pixels[p];
        Rgb sum;
        float weights = 0.f;
        for (int j = -2; j <= 2; ++j) {
          const int qy = y + j * step;
          if (qy < 0 || qy >= h) continue;
          for (int i = -2; i <= 2; ++i) {
            const int qx = x + i * step;
            if (qx < 0 || qx >= w) continue;
            const size_t q = size_t(qy) * size_t(w) + size_t(qx);
            if (g.hit[p] != g.hit[q]) continue;
            float e = squared(in.pixels[q] - cp) * s.inv_colour2;
            if (g.hit[p]) {
              const float pixels = step * std::sqrt(float(i * i + j * j));
              const float scale = g.footprint[p] * (pixels > 0.f ? pixels : 1.f);
              e += length_squared(g.normal[q] - g.normal[p]) * s.inv_normal2;
              e += length_squared(g.position[q] - g.position[p]) / (scale * scale) * s.inv_position2;
              e += squared(g.albedo[q] - g.albedo[p]) * s.inv_albedo2;
            }
            const float weight = kB3[i + 2] * kB3[j + 2] * std::exp(-e);
            sum += in.pixels[q] * weight;
            weights += weight;
          }
        }
        // The centre tap has weight h(0) > 0 (every distance is 0), so weights > 0.
        out->pixels[p] = sum * (1.f / weights);
      }
    }
  });
}

}  // namespace

Image atrous_filter(const Image& colour, const GuideBuffers& guide, const AtrousSettings& settings) {
  if (colour.width != guide.width || colour.height != guide.height)
    throw Error(fmt::format("atrous_filter: image {}x{} but guides {}x{}", colour.width, colour.height, guide.width, guide.height));
  if (settings.iterations < 0 || !(settings.sigma_colour > 0) || !(settings.sigma_normal > 0) || !(settings.sigma_position > 0) ||
      !(settings.sigma_albedo > 0))
    throw Error("atrous_filter: iterations must be >= 0 and every sigma positive");
  Image a = colour, b(colour.width, colour.height);
  for (int it = 0; it < settings.iterations; ++it) {
    const float sigma_colour = settings.sigma_colour * std::ldexp(1.f, -it);
    const Sigmas s{1.f / (sigma_colour * sigma_colour), 1.f / (settings.sigma_normal * settings.sigma_normal),
                   1.f / (settings.sigma_position * settings.sigma_position), 1.f / (settings.sigma_albedo * settings.sigma_albedo)};
    iterate(a, guide, 1 << it, s, &b);
    std::swap(a, b);
  }
  return a;
}

}  // namespace pathspace::study
