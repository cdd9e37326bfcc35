#include "pathspace/io/pbrt/pbrt_animated_transform.h"

#include <algorithm>
#include <cmath>

namespace pathspace::pbrt {

namespace {

using M3 = double[3][3];

bool invert3(const M3& a, M3& out) {
  const double det = a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
                     a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
  if (!(std::fabs(det) > 1e-300) || !std::isfinite(det)) return false;
  const double inv = 1.0 / det;
  out[0][0] = (a[1][1] * a[2][2] - a[1][2] * a[2][1]) * inv;
  out[0][1] = (a[0][2] * a[2][1] - a[0][1] * a[2][2]) * inv;
  out[0][2] = (a[0][1] * a[1][2] - a[0][2] * a[1][1]) * inv;
  out[1][0] = (a[1][2] * a[2][0] - a[1][0] * a[2][2]) * inv;
  out[1][1] = (a[0][0] * a[2][2] - a[0][2] * a[2][0]) * inv;
  out[1][2] = (a[0][2] * a[1][0] - a[0][0] * a[1][2]) * inv;
  out[2][0] = (a[1][0] * a[2][1] - a[1][1] * a[2][0]) * inv;
  out[2][1] = (a[0][1] * a[2][0] - a[0][0] * a[2][1]) * inv;
  out[2][2] = (a[0][0] * a[1][1] - a[0][1] * a[1][0]) * inv;
  return true;
}

// The unit quaternion of rotation matrix r (Shepperd's method: the largest diagonal term first).
Quaternion to_quaternion(const M3& r) {
  Quaternion q;
  const double trace = r[0][0] + r[1][1] + r[2][2];
  if (trace > 0.0) {
    const double s = std::sqrt(trace + 1.0) * 2.0;
    q.w = 0.25 * s;
    q.x = (r[2][1] - r[1][2]) / s;
    q.y = (r[0][2] - r[2][0]) / s;
    q.z = (r[1][0] - r[0][1]) / s;
  } else if (r[0][0] > r[1][1] && r[0][0] > r[2][2]) {
    const double s = std::sqrt(1.0 + r[0][0] - r[1][1] - r[2][2]) * 2.0;
    q.w = (r[2][1] - r[1][2]) / s;
    q.x = 0.25 * s;
    q.y = (r[0][1] + r[1][0]) / s;
    q.z = (r[0][2] + r[2][0]) / s;
  } else if (r[1][1] > r[2][2]) {
    const double s = std::sqrt(1.0 + r[1][1] - r[0][0] - r[2][2]) * 2.0;
    q.w = (r[0][2] - r[2][0]) / s;
    q.x = (r[0][1] + r[1][0]) / s;
    q.y = 0.25 * s;
    q.z = (r[1][2] + r[2][1]) / s;
  } else {
    const double s = std::sqrt(1.0 + r[2][2] - r[0][0] - r[1][1]) * 2.0;
    q.w = (r[1][0] - r[0][1]) / s;
    q.x = (r[0][2] + r[2][0]) / s;
    q.y = (r[1][2] + r[2][1]) / s;
    q.z = 0.25 * s;
  }
  const double n = std::sqrt(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z);
  return {q.w / n, q.x / n, q.y / n, q.z / n};
}

void to_matrix(const Quaternion& q, M3& r) {
  const double w = q.w, x = q.x, y = q.y, z = q.z;
  r[0][0] = 1 - 2 * (y * y + z * z), r[0][1] = 2 * (x * y - w * z), r[0][2] = 2 * (x * z + w * y);
  r[1][0] = 2 * (x * y + w * z), r[1][1] = 1 - 2 * (x * x + z * z), r[1][2] = 2 * (y * z - w * x);
  r[2][0] = 2 * (x * z - w * y), r[2][1] = 2 * (y * z + w * x), r[2][2] = 1 - 2 * (x * x + y * y);
}

double dot(const Quaternion& a, const Quaternion& b) { return a.w * b.w + a.x * b.x + a.y * b.y + a.z * b.z; }

// Shortest-arc slerp (pbrt-v4 flips b when the dot product is negative, as here).
Quaternion slerp(const Quaternion& a, Quaternion b, double t) {
  double c = dot(a, b);
  if (c < 0.0) {
    b = {-b.w, -b.x, -b.y, -b.z};
    c = -c;
  }
  if (c > 0.9995) {  // nearly parallel: normalized lerp
    Quaternion q{a.w + t * (b.w - a.w), a.x + t * (b.x - a.x), a.y + t * (b.y - a.y), a.z + t * (b.z - a.z)};
    const double n = std::sqrt(dot(q, q));
    return {q.w / n, q.x / n, q.y / n, q.z / n};
  }
  const double theta = std::acos(std::clamp(c, -1.0, 1.0)), s = std::sin(theta);
  const double wa = std::sin((1.0 - t) * theta) / s, wb = std::sin(t * theta) / s;
  return {wa * a.w + wb * b.w, wa * a.x + wb * b.x, wa * a.y + wb * b.y, wa * a.z + wb * b.z};
}

}  // namespace

bool decompose_transform(const Mat4& m, DecomposedTransform* out) {
  for (int i = 0; i < 3; ++i) out->t[i] = m.m[i][3];
  M3 a;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) a[i][j] = m.m[i][j];
  // Polar decomposition by averaging with the inverse transpose until it stops changing.
  M3 r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r[i][j] = a[i][j];
  bool converged = false;
  for (int iteration = 0; iteration < 100 && !converged; ++iteration) {
    M3 inv;
    if (!invert3(r, inv)) return false;
    double change = 0.0;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        const double next = 0.5 * (r[i][j] + inv[j][i]);
        change = std::max(change, std::fabs(next - r[i][j]));
        r[i][j] = next;
      }
    converged = change < 1e-12;
  }
  if (!converged) return false;
  // A reflection stays in S (pbrt-v4 keeps det(R) > 0 the same way).
  const double det = r[0][0] * (r[1][1] * r[2][2] - r[1][2] * r[2][1]) - r[0][1] * (r[1][0] * r[2][2] - r[1][2] * r[2][0]) +
                     r[0][2] * (r[1][0] * r[2][1] - r[1][1] * r[2][0]);
  if (det < 0.0)
    for (auto& row : r)
      for (double& v : row) v = -v;
  out->r = to_quaternion(r);
  M3 r_inv;
  if (!invert3(r, r_inv)) return false;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      double s = 0.0;
      for (int k = 0; k < 3; ++k) s += r_inv[i][k] * a[k][j];
      out->s[i][j] = s;
    }
  return true;
}

Mat4 compose_transform(const DecomposedTransform& d) {
  M3 r;
  to_matrix(d.r, r);
  Mat4 m;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      double v = 0.0;
      for (int k = 0; k < 3; ++k) v += r[i][k] * d.s[k][j];
      m.m[i][j] = v;
    }
    m.m[i][3] = d.t[i];
  }
  return m;
}

bool interpolate_transform(const Mat4& start, const Mat4& end, double s, Mat4* out) {
  if (s <= 0.0) {
    *out = start;
    return true;
  }
  if (s >= 1.0) {
    *out = end;
    return true;
  }
  DecomposedTransform a, b, c;
  if (!decompose_transform(start, &a) || !decompose_transform(end, &b)) return false;
  for (int i = 0; i < 3; ++i) c.t[i] = (1.0 - s) * a.t[i] + s * b.t[i];
  c.r = slerp(a.r, b.r, s);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) c.s[i][j] = (1.0 - s) * a.s[i][j] + s * b.s[i][j];
  *out = compose_transform(c);
  return true;
}

bool animated_transform_at(const Mat4& start, const Mat4& end, double t0, double t1, double time, Mat4* out) {
  const double s = t1 > t0 ? std::clamp((time - t0) / (t1 - t0), 0.0, 1.0) : (time >= t1 ? 1.0 : 0.0);
  return interpolate_transform(start, end, s, out);
}

double rotation_between_degrees(const Mat4& start, const Mat4& end) {
  DecomposedTransform a, b;
  if (!decompose_transform(start, &a) || !decompose_transform(end, &b)) return 0.0;
  const double c = std::fabs(dot(a.r, b.r));
  return 2.0 * std::acos(std::min(1.0, c)) * 180.0 / M_PI;
}

}  // namespace pathspace::pbrt
