// glTF channel sampling (see gltf_interpolation.h). Channels were checked when read (gltf_channels.h):
// at least one key, strictly increasing times, value counts matching, rotation values of unit length.
#include "pathspace/io/gltf/gltf_interpolation.h"

#include <algorithm>
#include <cmath>

namespace pathspace::gltf {

namespace {

double dot(const Quaternion& a, const Quaternion& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3]; }

// False for a (near) zero quaternion, which has no rotation to normalise to.
bool normalize(Quaternion* q) {
  const double len = std::sqrt(dot(*q, *q));
  if (!(len > 1e-12)) return false;
  for (double& x : *q) x /= len;
  return true;
}

// The `index`-th stored value (components() numbers; CUBICSPLINE: in-tangent, value, out-tangent per key).
const double* value(const Channel& ch, size_t index) { return ch.values.data() + index * ch.components(); }

// The value of key `key`.
const double* key_value(const Channel& ch, size_t key) {
  return value(ch, ch.interpolation == Interpolation::cubic_spline ? 3 * key + 1 : key);
}

Quaternion quaternion(const double* q) { return {q[0], q[1], q[2], q[3]}; }

}  // namespace

Quaternion slerp(const Quaternion& a, const Quaternion& b_in, double u) {
  Quaternion b = b_in;
  double d = dot(a, b);
  if (d < 0.0) {  // q and -q are the same rotation: take the one on a's side, the shorter arc
    for (double& x : b) x = -x;
    d = -d;
  }
  Quaternion r;
  if (d > 0.9995) {  // nearly parallel: sin(theta) vanishes, a normalised lerp is exact enough
    for (size_t i = 0; i < 4; ++i) r[i] = a[i] + u * (b[i] - a[i]);
  } else {
    const double theta = std::acos(d), s = std::sin(theta);
    const double wa = std::sin((1.0 - u) * theta) / s, wb = std::sin(u * theta) / s;
    for (size_t i = 0; i < 4; ++i) r[i] = wa * a[i] + wb * b[i];
  }
  normalize(&r);  // cannot fail: a and b are unit quaternions on the same side
  return r;
}

std::vector<double> sample_values(const Channel& ch, double seconds) {
  const std::vector<double>& t = ch.times;
  const size_t n = ch.components();
  const auto copy = [n](const double* v) { return std::vector<double>(v, v + n); };
  if (!(seconds > t.front())) return copy(key_value(ch, 0));  // before the first key (or at it): clamped
  if (seconds >= t.back()) return copy(key_value(ch, t.size() - 1));
  const size_t k = size_t(std::upper_bound(t.begin(), t.end(), seconds) - t.begin()) - 1;  // t[k] <= seconds < t[k+1]
  const double dt = t[k + 1] - t[k], u = (seconds - t[k]) / dt;
  const bool rotation = ch.property == AnimatedProperty::rotation;
  switch (ch.interpolation) {
    case Interpolation::step: return copy(key_value(ch, k));
    case Interpolation::linear: {
      const double *a = key_value(ch, k), *b = key_value(ch, k + 1);
      if (rotation) {
        const Quaternion q = slerp(quaternion(a), quaternion(b), u);
        return {q.begin(), q.end()};
      }
      std::vector<double> r(n);
      for (size_t i = 0; i < n; ++i) r[i] = a[i] + u * (b[i] - a[i]);
      return r;
    }
    case Interpolation::cubic_spline: {
      const double *v0 = value(ch, 3 * k + 1), *out0 = value(ch, 3 * k + 2);
      const double *in1 = value(ch, 3 * (k + 1)), *v1 = value(ch, 3 * (k + 1) + 1);
      const double u2 = u * u, u3 = u2 * u;
      const double h00 = 2 * u3 - 3 * u2 + 1, h10 = u3 - 2 * u2 + u, h01 = -2 * u3 + 3 * u2, h11 = u3 - u2;
      std::vector<double> r(n);
      for (size_t i = 0; i < n; ++i) r[i] = h00 * v0[i] + h10 * dt * out0[i] + h01 * v1[i] + h11 * dt * in1[i];
      if (rotation) {
        // Tangents can pull a rotation through zero; the spherical path between the two keys stands in.
        Quaternion q = quaternion(r.data());
        if (!normalize(&q)) q = slerp(quaternion(v0), quaternion(v1), u);
        return {q.begin(), q.end()};
      }
      return r;
    }
  }
  return copy(key_value(ch, k));
}

std::array<double, 4> sample(const Channel& ch, double seconds) {
  const std::vector<double> v = sample_values(ch, seconds);
  std::array<double, 4> r{0, 0, 0, 0};
  std::copy_n(v.begin(), std::min<size_t>(4, v.size()), r.begin());
  return r;
}

}  // namespace pathspace::gltf
