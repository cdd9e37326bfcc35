#include "pathspace/scene/environment_image.h"

#include <algorithm>
#include <cmath>

#include "pathspace/base/error.h"

namespace pathspace {

namespace {
float clamped_luminance(const Rgb& c) {
  return luminance(Rgb(std::max(c.r, 0.f), std::max(c.g, 0.f), std::max(c.b, 0.f)));
}

// Gram-Schmidt on the given axes, keeping their handedness (a mirrored map stays mirrored).
void orthonormalise(Vec3* x, Vec3* y, Vec3* z) {
  const float handed = dot(cross(*x, *y), *z) < 0.f ? -1.f : 1.f;
  *z = normalize(*z);
  *x = normalize(*x - *z * dot(*x, *z));
  *y = cross(*z, *x) * handed;
}
}  // namespace

void EnvironmentImage::prepare() {
  if (width <= 0 || height <= 0 || texels.size() != size_t(width) * size_t(height))
    throw Error("environment image '" + name + "' has no or inconsistent texels");
  if (mapping == EnvironmentMapping::equal_area && width != height)
    throw Error("environment image '" + name + "': the equal-area mapping needs a square image");
  for (const Vec3* a : {&axis_x, &axis_y, &axis_z})
    if (!all_finite(*a) || !(length(*a) > 0.f)) throw Error("environment image '" + name + "': degenerate transform");
  if (!(std::fabs(dot(cross(axis_x, axis_y), axis_z)) > 1e-6f * length(axis_x) * length(axis_y) * length(axis_z)))
    throw Error("environment image '" + name + "': singular transform");
  orthonormalise(&axis_x, &axis_y, &axis_z);

  const size_t w = size_t(width), h = size_t(height);
  std::vector<float> weights(w * h);
  double sum[3] = {0, 0, 0}, total_weight = 0;
  max_texel_ = 0.f;
  for (size_t y = 0; y < h; ++y) {
    // Lat-long rows shrink by sin(theta) on the sphere; equal-area texels all cover 4 pi / (w h).
    const double sin_theta = mapping == EnvironmentMapping::lat_long ? std::sin(M_PI * (double(y) + 0.5) / double(h)) : 1.0;
    for (size_t x = 0; x < w; ++x) {
      const Rgb& t = texels[y * w + x];
      if (!all_finite(t)) throw Error("environment image '" + name + "' holds NaN or infinite values");
      max_texel_ = std::max(max_texel_, max_component(t));
      for (int c = 0; c < 3; ++c) sum[c] += sin_theta * double(t[c]);
      total_weight += sin_theta;
      float lum = clamped_luminance(t);
      if (mapping == EnvironmentMapping::lat_long) {
        // Bilinear lookups inside this cell reach the 8 neighbours: their mean keeps the density
        // positive wherever the interpolated radiance is (NEE alone must see every bright texel).
        lum = 0.f;
        for (int dy = -1; dy <= 1; ++dy)
          for (int dx = -1; dx <= 1; ++dx) {
            const size_t yy = size_t(std::clamp(int(y) + dy, 0, height - 1));
            const size_t xx = (x + w + size_t(dx + 1) - 1) % w;
            lum += clamped_luminance(texels[yy * w + xx]);
          }
        lum /= 9.f;
      }
      weights[y * w + x] = float(double(lum) * sin_theta);
    }
  }
  sphere_mean_ = total_weight > 0 ? Rgb(float(sum[0] / total_weight), float(sum[1] / total_weight), float(sum[2] / total_weight)) : Rgb();
  distribution_.build(weights, width, height);
}

EnvironmentMapView EnvironmentImage::view() const {
  EnvironmentMapView v;
  if (texels.empty()) return v;
  v.texels = texels.data();
  v.width = width;
  v.height = height;
  v.mapping = mapping;
  v.axis_x = axis_x;
  v.axis_y = axis_y;
  v.axis_z = axis_z;
  v.distribution = distribution_.view();
  v.max_texel = max_texel_;
  return v;
}

}  // namespace pathspace
