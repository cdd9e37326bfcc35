#include "pathspace/camera/camera_animation.h"

#include <algorithm>
#include <cmath>

namespace pathspace {

namespace {

Vec3 lerp(const Vec3& a, const Vec3& b, float t) { return a + (b - a) * t; }

// Rodrigues' rotation of v about the unit axis k.
Vec3 rotate(const Vec3& v, const Vec3& k, float cos_a, float sin_a) {
  return v * cos_a + cross(k, v) * sin_a + k * (dot(k, v) * (1.f - cos_a));
}

}  // namespace

CameraKeyframe CameraPath::at(double time) const {
  if (keys.empty()) return {};
  if (!(time > keys.front().time)) return keys.front();
  if (time >= keys.back().time) return keys.back();
  // The first keyframe later than `time` and the one before it.
  const auto next = std::upper_bound(keys.begin(), keys.end(), time, [](double t, const CameraKeyframe& k) { return t < k.time; });
  const CameraKeyframe& a = *(next - 1);
  const CameraKeyframe& b = *next;
  const float t = float((time - a.time) / (b.time - a.time));
  CameraKeyframe k;
  k.time = time;
  k.position = lerp(a.position, b.position, t);
  k.target = lerp(a.target, b.target, t);
  k.up = lerp(a.up, b.up, t);
  // A keyframe without a field of view keeps the scene's; between one with and one without, the
  // one given holds.
  k.fov_degrees = a.fov_degrees > 0.f && b.fov_degrees > 0.f ? a.fov_degrees + (b.fov_degrees - a.fov_degrees) * t
                                                             : std::max(a.fov_degrees, b.fov_degrees);
  return k;
}

PerspectiveCamera camera_at_keyframe(const PerspectiveCamera& base, const CameraKeyframe& key) {
  PerspectiveCamera c = base;
  c.position = key.position;
  c.forward = normalize(key.target - key.position);
  c.right = normalize(cross(c.forward, key.up));
  c.up = cross(c.right, c.forward);
  if (key.fov_degrees > 0.f) set_shorter_axis_fov(&c, key.fov_degrees);
  return c;
}

PerspectiveCamera orbit_camera(const PerspectiveCamera& camera, const Vec3& centre, const Vec3& axis, float degrees) {
  const Vec3 k = normalize(axis);
  const float a = radians(degrees);
  const float cos_a = std::cos(a), sin_a = std::sin(a);
  PerspectiveCamera c = camera;
  c.position = centre + rotate(camera.position - centre, k, cos_a, sin_a);
  c.forward = normalize(rotate(camera.forward, k, cos_a, sin_a));
  c.right = normalize(rotate(camera.right, k, cos_a, sin_a));
  c.up = normalize(rotate(camera.up, k, cos_a, sin_a));
  return c;
}

}  // namespace pathspace
