// 4x4 affine transforms for the pbrt-v4 graphics state (double precision, host only). pbrt applies
// a directive T as CTM = CTM * T, lists Transform/ConcatTransform matrices column by column, and
// builds LookAt with right = cross(up, dir) (its left-handed convention), all reproduced here.
#pragma once

#include <cmath>
#include <optional>

#include "pathspace/math/frame.h"
#include "pathspace/math/vec3.h"

namespace pathspace::pbrt {

struct Mat4 {
  double m[4][4] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}};

  static Mat4 from_columns(const double* v) {  // pbrt's Transform [16 numbers]
    Mat4 r;
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) r.m[i][j] = v[j * 4 + i];
    return r;
  }
  static Mat4 translate(double x, double y, double z) {
    Mat4 r;
    r.m[0][3] = x, r.m[1][3] = y, r.m[2][3] = z;
    return r;
  }
  static Mat4 scale(double x, double y, double z) {
    Mat4 r;
    r.m[0][0] = x, r.m[1][1] = y, r.m[2][2] = z;
    return r;
  }
  // Rotation by `degrees` about `axis` (right-hand rule for column vectors, as pbrt's Rotate); none
  // when the axis has no direction (zero or not finite) and the angle is not 0, which the scene
  // readers report as an error rather than guess a rotation.
  static std::optional<Mat4> rotate(double degrees, double ax, double ay, double az) {
    const double len = std::sqrt(ax * ax + ay * ay + az * az);
    Mat4 r;
    if (!(len > 0.0) || !std::isfinite(len)) return degrees == 0.0 ? std::optional<Mat4>(r) : std::nullopt;
    ax /= len, ay /= len, az /= len;
    const double t = degrees * M_PI / 180.0, s = std::sin(t), c = std::cos(t);
    r.m[0][0] = ax * ax + (1 - ax * ax) * c;
    r.m[0][1] = ax * ay * (1 - c) - az * s;
    r.m[0][2] = ax * az * (1 - c) + ay * s;
    r.m[1][0] = ax * ay * (1 - c) + az * s;
    r.m[1][1] = ay * ay + (1 - ay * ay) * c;
    r.m[1][2] = ay * az * (1 - c) - ax * s;
    r.m[2][0] = ax * az * (1 - c) - ay * s;
    r.m[2][1] = ay * az * (1 - c) + ax * s;
    r.m[2][2] = az * az + (1 - az * az) * c;
    return r;
  }

  bool operator==(const Mat4& b) const {
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j)
        if (m[i][j] != b.m[i][j]) return false;
    return true;
  }

  Mat4 operator*(const Mat4& b) const {
    Mat4 r;
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) {
        double s = 0;
        for (int k = 0; k < 4; ++k) s += m[i][k] * b.m[k][j];
        r.m[i][j] = s;
      }
    return r;
  }

  double det3() const {
    return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
           m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
  }

  // Inverse by Gauss-Jordan elimination with partial pivoting; false when singular.
  bool inverse(Mat4* out) const {
    double a[4][8];
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) a[i][j] = m[i][j], a[i][j + 4] = i == j ? 1.0 : 0.0;
    for (int c = 0; c < 4; ++c) {
      int p = c;
      for (int r = c + 1; r < 4; ++r)
        if (std::fabs(a[r][c]) > std::fabs(a[p][c])) p = r;
      if (std::fabs(a[p][c]) < 1e-300) return false;
      for (int j = 0; j < 8; ++j) std::swap(a[c][j], a[p][j]);
      const double inv = 1.0 / a[c][c];
      for (int j = 0; j < 8; ++j) a[c][j] *= inv;
      for (int r = 0; r < 4; ++r)
        if (r != c) {
          const double f = a[r][c];
          for (int j = 0; j < 8; ++j) a[r][j] -= f * a[c][j];
        }
    }
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) out->m[i][j] = a[i][j + 4];
    return true;
  }

  Vec3 point(const Vec3& p) const {
    double r[4];
    for (int i = 0; i < 4; ++i) r[i] = m[i][0] * p.x + m[i][1] * p.y + m[i][2] * p.z + m[i][3];
    const double w = r[3] == 0.0 ? 1.0 : r[3];
    return Vec3(float(r[0] / w), float(r[1] / w), float(r[2] / w));
  }
  Vec3 vector(const Vec3& v) const {
    return Vec3(float(m[0][0] * v.x + m[0][1] * v.y + m[0][2] * v.z), float(m[1][0] * v.x + m[1][1] * v.y + m[1][2] * v.z),
                float(m[2][0] * v.x + m[2][1] * v.y + m[2][2] * v.z));
  }
  // Normals transform with the inverse transpose; pass the inverse matrix.
  static Vec3 normal(const Mat4& inv, const Vec3& n) {
    return Vec3(float(inv.m[0][0] * n.x + inv.m[1][0] * n.y + inv.m[2][0] * n.z),
                float(inv.m[0][1] * n.x + inv.m[1][1] * n.y + inv.m[2][1] * n.z),
                float(inv.m[0][2] * n.x + inv.m[1][2] * n.y + inv.m[2][2] * n.z));
  }
};

// pbrt-v4's LookAt: the camera-from-world matrix (the inverse of [right, up', dir, eye]).
inline bool look_at(const Vec3& eye, const Vec3& target, const Vec3& up, Mat4* camera_from_world) {
  const Vec3 dir = normalize(target - eye);
  const Vec3 r = cross(normalize(up), dir);
  if (!(length(r) > 1e-8f) || !all_finite(dir)) return false;
  const Vec3 right = normalize(r);
  const Vec3 new_up = cross(dir, right);
  Mat4 world_from_camera;
  const Vec3 cols[4] = {right, new_up, dir, eye};
  for (int j = 0; j < 4; ++j) {
    world_from_camera.m[0][j] = cols[j].x;
    world_from_camera.m[1][j] = cols[j].y;
    world_from_camera.m[2][j] = cols[j].z;
  }
  return world_from_camera.inverse(camera_from_world);
}

// The orthonormal frame nearest to m's axes by Gram-Schmidt from its z axis (n = z; s from x; t from
// y): how a light's image plane is placed under a transform that may scale or shear it. False when
// an axis is zero or not finite, or x or y is parallel to z.
inline bool axes_frame(const Mat4& m, Frame* out) {
  const Vec3 x = m.vector(Vec3(1, 0, 0)), y = m.vector(Vec3(0, 1, 0)), z = m.vector(Vec3(0, 0, 1));
  if (!(length(x) > 0.f && length(y) > 0.f && length(z) > 0.f) || !all_finite(x) || !all_finite(y) || !all_finite(z)) return false;
  const Vec3 n = normalize(z);
  const Vec3 s = normalize(x - n * dot(x, n));
  const Vec3 t = normalize(y - n * dot(y, n) - s * dot(y, s));
  if (!all_finite(s) || !all_finite(t)) return false;
  *out = Frame(s, t, n);
  return true;
}

}  // namespace pathspace::pbrt
