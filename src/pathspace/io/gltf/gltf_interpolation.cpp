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

std::array<double, 4> value(const Channel& ch, size_t index) {
  std::array<double, 4> v{0, 0, 0, 0};
  std::copy_n(ch.values.begin() + std::ptrdiff_t(index * ch.components()), ch.components(), v.begin());
  return v;
}

// CUBICSPLINE stores in-tangent, value, out-tangent for every key.
std::array<double, 4> key_value(const Channel& ch, size_t key) {
  return value(ch, ch.interpolation == Interpolation::cubic_spline ? 3 * key + 1 : key);
}

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

std::array<double, 4> sample(const Channel& ch, double seconds) {
  const std::vector<double>& t = ch.times;
  if (!(seconds > t.front())) return key_value(ch, 0);  // before the first key (or at it): clamped
  if (seconds >= t.back()) return key_value(ch, t.size() - 1);
  const size_t k = size_t(std::upper_bound(t.begin(), t.end(), seconds) - t.begin()) - 1;  // t[k] <= seconds < t[k+1]
  const double dt = t[k + 1] - t[k], u = (seconds - t[k]) / dt;
  const bool rotation = ch.property == AnimatedProperty::rotation;
  switch (ch.interpolation) {
    case Interpolation::step: return key_value(ch, k);
    case Interpolation::linear: {
      const std::array<double, 4> a = key_value(ch, k), b = key_value(ch, k + 1);
      if (rotation) return slerp(a, b, u);
      std::array<double, 4> r{0, 0, 0, 0};
      for (size_t i = 0; i < 3; ++i) r[i] = a[i] + u * (b[i] - a[i]);
      return r;
    }
    case Interpolation::cubic_spline: {
      const std::array<double, 4> v0 = value(ch, 3 * k + 1), out0 = value(ch, 3 * k + 2);
      const std::array<double, 4> in1 = value(ch, 3 * (k + 1)), v1 = value(ch, 3 * (k + 1) + 1);
      const double u2 = u * u, u3 = u2 * u;
      const double h00 = 2 * u3 - 3 * u2 + 1, h10 = u3 - 2 * u2 + u, h01 = -2 * u3 + 3 * u2, h11 = u3 - u2;
      std::array<double, 4> r{0, 0, 0, 0};
      for (size_t i = 0; i < ch.components(); ++i) r[i] = h00 * v0[i] + h10 * dt * out0[i] + h01 * v1[i] + h11 * dt * in1[i];
      // Tangents can pull a rotation through zero; the spherical path between the two keys stands in.
      if (rotation && !normalize(&r)) return slerp(v0, v1, u);
      return r;
    }
  }
  return key_value(ch, k);
}

}  // namespace pathspace::gltf
