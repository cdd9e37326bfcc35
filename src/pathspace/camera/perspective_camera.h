// Perspective camera (a pinhole for now): raster mapping, ray generation, importance We and its
// pdfs, and the camera connection used by light tracing, BPT and PCLT (PCLT paper eq. 4). Conventions: raster x right,
// y down, pixel (i, j) covers [i, i+1) x [j, j+1) (docs/conventions.md; cornell-variants.md §2).
//
// The image plane sits at distance 1 in front of the pinhole and spans [-tan_x, tan_x] x
// [-tan_y, tan_y]. A pixel's value is the mean radiance over its square on that plane, so the
// importance of a direction at angle theta to the view axis is We = 1 / (A_pixel cos^4 theta)
// for the pixel it falls in (A_pixel = plane area of one pixel).
#pragma once

#include "pathspace/geometry/ray.h"
#include "pathspace/sampling/warps.h"

namespace pathspace {

struct PerspectiveCamera {
  Vec3 position;
  Vec3 forward;  // unit view axis
  Vec3 right;    // unit, raster +x
  Vec3 up;       // unit, raster -y
  float tan_x = 0.f, tan_y = 0.f;  // half extents of the image plane at distance 1
  int width = 0, height = 0;

  PS_HD float pixel_area() const { return (2.f * tan_x / float(width)) * (2.f * tan_y / float(height)); }
  PS_HD float image_area() const { return 4.f * tan_x * tan_y; }

  // Unit direction through continuous raster position (rx, ry).
  PS_HD Vec3 direction(float rx, float ry) const {
    const float sx = (2.f * rx / float(width) - 1.f) * tan_x;
    const float sy = (1.f - 2.f * ry / float(height)) * tan_y;
    return normalize(forward + right * sx + up * sy);
  }
  PS_HD Ray generate_ray(float rx, float ry) const { return {position, direction(rx, ry), 0.f, kInfinity}; }

  // Inverse mapping: continuous raster position of a world direction; false when behind the
  // camera or outside [0, W) x [0, H).
  PS_HD bool raster_from_direction(const Vec3& d, float* rx, float* ry) const {
    const float c = dot(d, forward);
    if (c <= 0.f) return false;
    const float sx = dot(d, right) / c, sy = dot(d, up) / c;
    const float x = (sx / tan_x + 1.f) * 0.5f * float(width);
    const float y = (1.f - sy / tan_y) * 0.5f * float(height);
    if (!(x >= 0.f && x < float(width) && y >= 0.f && y < float(height))) return false;
    *rx = x;
    *ry = y;
    return true;
  }

  // Solid-angle density of generate_ray's direction when (rx, ry) is uniform over the image:
  // p(w) = 1 / (A_image cos^3 theta).
  PS_HD float pdf_direction(const Vec3& d) const {
    const float c = dot(d, forward);
    if (c <= 0.f) return 0.f;
    return 1.f / (image_area() * c * c * c);
  }

  // Importance of direction d for the pixel it falls in: 1 / (A_pixel cos^4 theta) (0 outside).
  PS_HD float importance(const Vec3& d) const {
    float rx, ry;
    if (!raster_from_direction(d, &rx, &ry)) return 0.f;
    const float c = dot(d, forward);
    return 1.f / (pixel_area() * c * c * c * c);
  }

  // Camera connection from a surface point p (t = 1 in BPT terms). On success gives the raster
  // position, the unit direction wi from p towards the camera, the distance, and the factor
  //   We cos(theta_cam) / dist^2 = 1 / (A_pixel cos^3 theta_cam dist^2)
  // that converts (throughput * f * |cos_surface|) into the pixel's radiance estimate for one
  // light path (divide by the number of light paths). Equals cornell-variants.md §2's splat.
  PS_HD bool connect(const Vec3& p, float* rx, float* ry, Vec3* wi, float* dist, float* factor) const {
    const Vec3 to_cam = position - p;
    const float d2 = length_squared(to_cam);
    const float d = sqrtf(d2);
    const Vec3 dir_from_cam = -to_cam / d;
    if (!raster_from_direction(dir_from_cam, rx, ry)) return false;
    const float c = dot(dir_from_cam, forward);
    *wi = to_cam / d;
    *dist = d;
    *factor = 1.f / (pixel_area() * c * c * c * d2);
    return true;
  }
};

// Camera from position, look direction, up hint and the horizontal full field of view.
// `square_pixels` = false reproduces SmallVCM's convention: the same tan for x and y
// (stretched pixels when W != H; cornell-variants.md §2).
inline PerspectiveCamera make_perspective_camera(const Vec3& position, const Vec3& forward_hint, const Vec3& up_hint,
                                         float hfov_degrees, int width, int height, bool square_pixels = true) {
  PerspectiveCamera c;
  c.position = position;
  c.forward = normalize(forward_hint);
  c.right = normalize(cross(c.forward, up_hint));
  c.up = cross(c.right, c.forward);
  c.tan_x = tanf(radians(hfov_degrees) * 0.5f);
  c.tan_y = square_pixels ? c.tan_x * float(height) / float(width) : c.tan_x;
  c.width = width;
  c.height = height;
  return c;
}

}  // namespace pathspace
