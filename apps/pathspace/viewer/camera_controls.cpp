#include "viewer/camera_controls.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

namespace pathspace::viewer {

namespace {

// v rotated by `degrees` about the unit axis (Rodrigues).
Vec3 rotated(const Vec3& v, const Vec3& axis, double degrees) {
  const float a = float(degrees * M_PI / 180.0), c = std::cos(a), s = std::sin(a);
  return v * c + cross(axis, v) * s + axis * (dot(axis, v) * (1.f - c));
}

std::string xyz(const Vec3& v) { return fmt::format("{:.6g},{:.6g},{:.6g}", v.x, v.y, v.z); }

}  // namespace

void move_camera(PerspectiveCamera* camera, double right, double up, double forward, float step) {
  camera->position += (camera->right * float(right) + camera->up * float(up) + camera->forward * float(forward)) * step;
}

void turn_camera(PerspectiveCamera* camera, double yaw_degrees, double pitch_degrees) {
  Vec3 forward = rotated(camera->forward, camera->up, yaw_degrees);
  Vec3 right = normalize(cross(forward, camera->up));
  forward = normalize(rotated(forward, right, pitch_degrees));
  camera->forward = forward;
  camera->right = right;
  camera->up = normalize(cross(right, forward));
}

std::string camera_options(const PerspectiveCamera& c) {
  const double fov = 2.0 * std::atan(std::min(c.tan_x, c.tan_y)) * 180.0 / M_PI;
  return fmt::format("--camera-pos {} --camera-target {} --camera-up {} --fov {:.6g}", xyz(c.position), xyz(c.position + c.forward),
                     xyz(c.up), fov);
}

}  // namespace pathspace::viewer
