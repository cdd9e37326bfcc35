// Perspective camera, pinhole or thin lens (depth of field, pbrt-v4's PerspectiveCamera model):
// raster mapping, ray generation, importance We and its pdfs, and the camera connection used by
// light tracing, BPT and PCLT (PCLT paper eq. 4). Conventions: raster x right, y down, pixel (i, j)
// covers [i, i+1) x [j, j+1) (docs/conventions.md; docs/scenes.md §2).
//
// The image plane sits at distance 1 in front of the lens centre and spans [-tan_x, tan_x] x
// [-tan_y, tan_y]. A pixel's value is the mean radiance over its square on that plane (and, for a
// thin lens, over the lens disk), so the importance of a direction at angle theta to the view axis
// is We = 1 / (A_pixel cos^4 theta) for a pinhole and We = 1 / (A_lens A_pixel cos^4 theta) from a
// lens point.
//
// Thin lens (lens_radius > 0): a lens point x0 is uniform on the disk of radius lens_radius in the
// plane through `position` spanned by right and up (pdf 1 / A_lens); raster position s on the image
// plane names the point F = position + focus_distance (forward + s) on the plane in focus, and the
// ray goes from x0 through F. Derivations:
//  * direction pdf: F is uniform over the focus plane's image (area A_image f^2) when s is uniform,
//    and dA(F) = dist^2 / cos dw with dist = f / cos seen from x0, so p(w | x0) = 1 / (A_image cos^3)
//    as for the pinhole (cos measured from x0).
//  * connection (t = 1): the light side samples x0 with pdf 1 / A_lens, so its factor is
//    We cos / (d^2 p_lens) = 1 / (A_pixel cos^3 d^2) with cos and d measured from x0: the pinhole
//    formula at the lens point. The raster position of p is where the ray x0 -> p meets the focus
//    plane, seen from the lens centre: s = (p - x0)_{right,up} / (p - x0)_forward + offset / f.
//  * BPT MIS: both the camera subpath and every t = 1 connection sample x0 with the same 1 / A_lens,
//    so the lens density cancels from every ratio of strategy densities; only the directional pdf
//    and distances measured from the sampled x0 enter the weights. Light paths cannot hit the lens.
#pragma once

#include "pathspace/camera/pixel_filter.h"
#include "pathspace/geometry/ray.h"
#include "pathspace/sampling/warps.h"

namespace pathspace {

// A point projected onto the image through a lens point (unclipped raster position).
struct CameraProjection {
  float rx = 0.f, ry = 0.f;
  Vec3 wi;            // unit, from the point towards the lens point
  float dist = 0.f;   // to the lens point
  float factor = 0.f; // We cos_cam / (dist^2 p_lens) = 1 / (A_pixel cos^3 theta dist^2) (eq. 4 with A_p)
};

// Where a camera is and where it looks: the part of a PerspectiveCamera that moves during the
// shutter (motion blur, scene/motion.h). Axes unit and orthogonal.
struct CameraPose {
  Vec3 position, forward, right, up;
};

struct PerspectiveCamera {
  Vec3 position;  // the pinhole, or the centre of the lens
  Vec3 forward;   // unit view axis
  Vec3 right;     // unit, raster +x
  Vec3 up;        // unit, raster -y
  float tan_x = 0.f, tan_y = 0.f;  // half extents of the image plane at distance 1
  int width = 0, height = 0;
  float lens_radius = 0.f;     // 0: pinhole (no depth of field)
  float focus_distance = 1.f;  // distance of the plane in focus along forward (thin lens only)
  PixelFilter filter;          // the film's reconstruction filter (camera/pixel_filter.h)

  PS_HD bool is_pinhole() const { return !(lens_radius > 0.f); }
  PS_HD CameraPose pose() const { return {position, forward, right, up}; }
  PS_HD float pixel_area() const { return (2.f * tan_x / float(width)) * (2.f * tan_y / float(height)); }
  PS_HD float image_area() const { return 4.f * tan_x * tan_y; }

  // Offset of the lens point from the lens centre in (right, up) coordinates for a uniform sample
  // u in [0,1)^2 (concentric disk: uniform in area). Zero for a pinhole.
  PS_HD Point2 lens_offset(Point2 u) const {
    if (is_pinhole()) return {0.f, 0.f};
    const Point2 d = square_to_disk_concentric(u);
    return {lens_radius * d.x, lens_radius * d.y};
  }
  PS_HD Vec3 lens_point(Point2 offset) const { return is_pinhole() ? position : position + right * offset.x + up * offset.y; }

  // Unit direction from the lens centre through continuous raster position (rx, ry).
  PS_HD Vec3 direction(float rx, float ry) const {
    const float sx = (2.f * rx / float(width) - 1.f) * tan_x;
    const float sy = (1.f - 2.f * ry / float(height)) * tan_y;
    return normalize(forward + right * sx + up * sy);
  }
  // The chief ray through the lens centre (the pinhole ray; probes and masks, not rendering).
  PS_HD Ray generate_ray(float rx, float ry) const { return {position, direction(rx, ry), 0.f, kInfinity}; }
  // The camera ray for raster (rx, ry) and lens sample u: identical to generate_ray(rx, ry) for a
  // pinhole; through the lens point towards the raster position's point on the focus plane otherwise.
  PS_HD Ray generate_ray(float rx, float ry, Point2 lens_u) const {
    if (is_pinhole()) return generate_ray(rx, ry);
    const Point2 o = lens_offset(lens_u);
    const float inv_f = 1.f / focus_distance;
    const float sx = (2.f * rx / float(width) - 1.f) * tan_x - o.x * inv_f;
    const float sy = (1.f - 2.f * ry / float(height)) * tan_y - o.y * inv_f;
    return {lens_point(o), normalize(forward + right * sx + up * sy), 0.f, kInfinity};
  }

  // Inverse mapping from the lens centre: continuous raster position of a world direction; false
  // when behind the camera or outside [0, W) x [0, H).
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

  // Solid-angle density of a camera ray's direction (from its lens point) when (rx, ry) is uniform
  // over the image: p(w) = 1 / (A_image cos^3 theta), pinhole and thin lens alike (header comment).
  PS_HD float pdf_direction(const Vec3& d) const {
    const float c = dot(d, forward);
    if (c <= 0.f) return 0.f;
    return 1.f / (image_area() * c * c * c);
  }

  // Pinhole importance of direction d for the pixel it falls in: 1 / (A_pixel cos^4 theta) (0 outside).
  PS_HD float importance(const Vec3& d) const {
    float rx, ry;
    if (!raster_from_direction(d, &rx, &ry)) return 0.f;
    const float c = dot(d, forward);
    return 1.f / (pixel_area() * c * c * c * c);
  }

  // Projects p through the lens point of sample lens_u (ignored for a pinhole). The raster
  // position is not clipped to the image (a wide splat filter lets points just outside reach
  // border pixels); false behind the lens plane or for non-finite results.
  PS_HD bool project(const Vec3& p, Point2 lens_u, CameraProjection* out) const {
    const Point2 o = lens_offset(lens_u);
    const Vec3 to_cam = lens_point(o) - p;
    const float d2 = length_squared(to_cam);
    if (!(d2 > 0.f)) return false;
    const float d = sqrtf(d2);
    const Vec3 dir = -to_cam / d;  // from the lens point to p
    const float c = dot(dir, forward);
    if (c <= 0.f) return false;
    float sx = dot(dir, right) / c, sy = dot(dir, up) / c;
    if (!is_pinhole()) {  // where the ray meets the focus plane, seen from the lens centre
      sx += o.x / focus_distance;
      sy += o.y / focus_distance;
    }
    out->rx = (sx / tan_x + 1.f) * 0.5f * float(width);
    out->ry = (1.f - sy / tan_y) * 0.5f * float(height);
    out->wi = to_cam / d;
    out->dist = d;
    out->factor = 1.f / (pixel_area() * c * c * c * d2);
    return isfinite(out->rx) && isfinite(out->ry) && isfinite(out->factor);
  }

  // Camera connection from a surface point p (t = 1 in BPT terms): project() clipped to the image.
  // The factor converts (throughput * f * |cos_surface|) into the pixel's radiance estimate for one
  // light path (divide by the number of light paths). Equals docs/scenes.md §2's splat.
  PS_HD bool connect(const Vec3& p, Point2 lens_u, CameraProjection* out) const {
    if (!project(p, lens_u, out)) return false;
    return out->rx >= 0.f && out->rx < float(width) && out->ry >= 0.f && out->ry < float(height);
  }
};

// The camera at fraction t of the way from its own pose to `to`: the position on the straight line,
// the axes blended and made orthonormal again (forward first, then right from the blended up). The
// blend turns the camera at an uneven rate, which is invisible for the small turns of a shutter
// interval; the scene readers warn above kMaxLinearRotationDegrees (io/pbrt/pbrt_animated_transform.h).
PS_INLINE PerspectiveCamera camera_towards(const PerspectiveCamera& c, const CameraPose& to, float t) {
  PerspectiveCamera out = c;
  const float s = 1.f - t;
  out.position = c.position * s + to.position * t;
  out.forward = normalize(c.forward * s + to.forward * t);
  out.right = normalize(cross(out.forward, c.up * s + to.up * t));
  out.up = cross(out.right, out.forward);
  return out;
}

// Camera from position, look direction, up hint and the horizontal full field of view.
// `square_pixels` = false reproduces SmallVCM's convention: the same tan for x and y
// (stretched pixels when W != H; docs/scenes.md §2). A pinhole; set_thin_lens adds the lens.
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

// Sets the field of view of the shorter image axis (square pixels; pbrt's convention, used for scene
// files and camera paths).
inline void set_shorter_axis_fov(PerspectiveCamera* c, float fov_degrees) {
  const float t = tanf(radians(fov_degrees) * 0.5f);
  c->tan_x = c->width >= c->height ? t * float(c->width) / float(c->height) : t;
  c->tan_y = c->width >= c->height ? t : t * float(c->height) / float(c->width);
}

// Turns the camera into a thin lens (lens_radius > 0, focus_distance > 0; scene units), or back
// into a pinhole with lens_radius = 0. Returns false (camera unchanged) for invalid values.
inline bool set_thin_lens(PerspectiveCamera* c, float lens_radius, float focus_distance) {
  if (!(lens_radius >= 0.f && lens_radius < kInfinity)) return false;
  if (lens_radius > 0.f && !(focus_distance > 0.f && focus_distance < kInfinity)) return false;
  c->lens_radius = lens_radius;
  if (lens_radius > 0.f) c->focus_distance = focus_distance;
  return true;
}

}  // namespace pathspace
