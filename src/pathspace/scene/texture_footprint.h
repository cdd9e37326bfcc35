// Textures averaged over the footprint of a camera ray's pixel (`--texture-footprint`): at one sample
// per pixel a texture finer than the pixels aliases, since the pixel's one hit reads one texel while
// the pixel's true value averages many. Here the hit's textures are box-filtered over the pixel
// itself: the pixel's square on the image plane, seen from the ray's lens point, is projected onto
// the plane of the hit triangle (its four corners' texture coordinates: the ray differentials of
// Igehy 1999, to the pixel's corners rather than one pixel away), and each texture is read at up to
// 4 x 4 points spread over that quadrilateral, as many per axis as the footprint spans texels.
// Where the footprint spans less than one texel each way the point lookup at the hit is kept, so
// magnified textures stay as they were.
//
// The average is exact for the pixel's own plane; lighting, which stays a point sample at the hit,
// is not averaged, so the estimate is biased by how texture and lighting vary together inside one
// pixel (small unless a shadow edge crosses texture detail), in exchange for texture detail that
// converges at 1 spp per frame. Spheres and hits outside the image keep the point lookup.
#pragma once

#include "pathspace/geometry/interaction.h"
#include "pathspace/geometry/ray.h"
#include "pathspace/geometry/surface_attributes.h"
#include "pathspace/scene/motion.h"
#include "pathspace/scene/shading_material.h"

namespace pathspace {

constexpr int kMaxFootprintTaps = 4;  // texture lookups per footprint axis, at most

// Texture coordinates at the corners of a pixel's footprint: (x0, y0), (x1, y0), (x0, y1), (x1, y1).
struct PixelFootprint {
  Point2 uv[4];
};

namespace footprint_detail {
// Where the ray from `origin` along `dir` meets the plane of triangle (a, b, c), as barycentrics
// (b1, b2) of b and c, extended beyond the triangle; false when it misses the plane.
PS_INLINE bool plane_barycentrics(const TriangleVertices& t, const Vec3& origin, const Vec3& dir, float* b1, float* b2) {
  const Vec3 e1 = t.p1 - t.p0, e2 = t.p2 - t.p0;
  const Vec3 n = cross(e1, e2);
  const float denom = dot(dir, n);
  if (!(fabsf(denom) > 0.f)) return false;
  const float dist = dot(t.p0 - origin, n) / denom;
  if (!(dist > 0.f && dist < kInfinity)) return false;
  const Vec3 w = origin + dir * dist - t.p0;
  const float d00 = dot(e1, e1), d01 = dot(e1, e2), d11 = dot(e2, e2), d20 = dot(w, e1), d21 = dot(w, e2);
  const float det = d00 * d11 - d01 * d01;
  if (!(det > 0.f)) return false;
  *b1 = (d11 * d20 - d01 * d21) / det;
  *b2 = (d00 * d21 - d01 * d20) / det;
  return fabsf(*b1) < 1e6f && fabsf(*b2) < 1e6f;
}

// Lookups per axis for a footprint edge spanning `texels` texels.
PS_INLINE int taps_for(float texels) {
  if (!(texels > 1.f)) return 1;
  return texels >= float(kMaxFootprintTaps) ? kMaxFootprintTaps : int(ceilf(texels));
}

PS_INLINE float texel_length(const TextureView& t, Point2 a, Point2 b) {
  const float du = (b.x - a.x) * t.uscale * float(t.width), dv = (b.y - a.y) * t.vscale * float(t.height);
  return sqrtf(du * du + dv * dv);
}
}  // namespace footprint_detail

// The footprint of the pixel holding camera ray `ray` (from the camera at the hit's time) on the
// plane of the triangle it hit; false for spheres and rays outside the image.
PS_INLINE bool pixel_footprint(const SceneView& scene, const SurfaceHit& hit, const Ray& ray, PixelFootprint* out) {
  using footprint_detail::plane_barycentrics;
  if (hit.kind != ShapeKind::triangle || hit.prim >= scene.num_triangles) return false;
  const PerspectiveCamera cam = camera_at(scene, hit.time);
  // The focus plane's point of the ray (the image plane at distance 1 for a pinhole) names its pixel.
  const float along = dot(ray.d, cam.forward);
  if (!(along > 0.f)) return false;
  const float focus = cam.is_pinhole() ? 1.f : cam.focus_distance;
  const Vec3 on_focus = ray.o + ray.d * (focus / along) - cam.position;
  float rx, ry;
  if (!cam.raster_from_direction(on_focus, &rx, &ry)) return false;
  const float x0 = floorf(rx), y0 = floorf(ry);
  const Triangle& tri = scene.triangles[hit.prim];
  const TriangleVertices verts = triangle_at(scene, tri, hit.time);
  for (int k = 0; k < 4; ++k) {
    const float x = x0 + float(k & 1), y = y0 + float(k >> 1);
    const float sx = (2.f * x / float(cam.width) - 1.f) * cam.tan_x, sy = (1.f - 2.f * y / float(cam.height)) * cam.tan_y;
    const Vec3 corner = cam.position + (cam.forward + cam.right * sx + cam.up * sy) * focus;
    float b1, b2;
    if (!plane_barycentrics(verts, ray.o, corner - ray.o, &b1, &b2)) return false;
    out->uv[k] = triangle_uv(tri, scene.uvs, b1, b2);
  }
  return true;
}

// Texture `t` box-filtered over footprint `fp`; the point lookup at `uv` where the footprint spans
// less than a texel each way.
PS_INLINE Rgb footprint_texture_lookup(const TextureView& t, const PixelFootprint& fp, Point2 uv) {
  using namespace footprint_detail;
  const int nx = taps_for(fmaxf(texel_length(t, fp.uv[0], fp.uv[1]), texel_length(t, fp.uv[2], fp.uv[3])));
  const int ny = taps_for(fmaxf(texel_length(t, fp.uv[0], fp.uv[2]), texel_length(t, fp.uv[1], fp.uv[3])));
  if (nx == 1 && ny == 1) return texture_lookup(t, uv);
  Rgb sum;
  for (int j = 0; j < ny; ++j) {
    const float fy = (float(j) + 0.5f) / float(ny);
    const Point2 left{fp.uv[0].x + (fp.uv[2].x - fp.uv[0].x) * fy, fp.uv[0].y + (fp.uv[2].y - fp.uv[0].y) * fy};
    const Point2 right{fp.uv[1].x + (fp.uv[3].x - fp.uv[1].x) * fy, fp.uv[1].y + (fp.uv[3].y - fp.uv[1].y) * fy};
    for (int i = 0; i < nx; ++i) {
      const float fx = (float(i) + 0.5f) / float(nx);
      sum += texture_lookup(t, {left.x + (right.x - left.x) * fx, left.y + (right.y - left.y) * fx});
    }
  }
  return sum * (1.f / float(nx * ny));
}

struct FootprintTextureLookup {
  const PixelFootprint& footprint;
  Point2 uv;  // the hit's: the point lookup of magnified textures
  PS_HD Rgb operator()(const TextureView& t) const { return footprint_texture_lookup(t, footprint, uv); }
};

// shading_material for a camera ray's hit with its textures averaged over the pixel's footprint:
// the scene's record when the material has no textures, else the filtered copy in *storage.
PS_INLINE const Material& footprint_shading_material(const SceneView& scene, const SurfaceHit& hit, const Ray& camera_ray,
                                                     Material* storage) {
  const Material& m = scene.materials[hit.material];
  if (!has_textures(m)) return m;
  PixelFootprint fp;
  if (!pixel_footprint(scene, hit, camera_ray, &fp)) return shading_material(scene, hit, storage);
  *storage = textured_material(scene, hit.material, FootprintTextureLookup{fp, hit.uv});
  return *storage;
}

}  // namespace pathspace
