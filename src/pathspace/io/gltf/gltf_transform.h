// Node transforms of a glTF scene graph: a node's local matrix is its `matrix` (column-major) or
// T * R * S from translation, rotation (unit quaternion x, y, z, w) and scale; world = parent * local.
// Animations (gltf_animation.h) replace parts of a node's T, R and S.
// Affine 3x4 in double, so long chains of nodes do not lose precision before the final float.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "pathspace/io/gltf/gltf_context.h"
#include "pathspace/math/vec3.h"

namespace pathspace::gltf {

struct Affine {
  std::array<std::array<double, 4>, 3> m{{{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}}};  // rows

  Vec3 point(const Vec3& p) const { return apply(p, 1.0); }
  Vec3 vector(const Vec3& v) const { return apply(v, 0.0); }
  double determinant() const {
    return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
           m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
  }
  // Normals transform with the inverse transpose; the cofactor matrix is that up to a positive
  // factor times det, so with the sign of det it gives the right direction (normalised by the caller).
  Vec3 normal(const Vec3& n) const {
    const double s = determinant() < 0.0 ? -1.0 : 1.0;
    const double c[3][3] = {{m[1][1] * m[2][2] - m[1][2] * m[2][1], m[1][2] * m[2][0] - m[1][0] * m[2][2], m[1][0] * m[2][1] - m[1][1] * m[2][0]},
                            {m[0][2] * m[2][1] - m[0][1] * m[2][2], m[0][0] * m[2][2] - m[0][2] * m[2][0], m[0][1] * m[2][0] - m[0][0] * m[2][1]},
                            {m[0][1] * m[1][2] - m[0][2] * m[1][1], m[0][2] * m[1][0] - m[0][0] * m[1][2], m[0][0] * m[1][1] - m[0][1] * m[1][0]}};
    Vec3 out;
    for (int i = 0; i < 3; ++i) out[i] = float(s * (c[i][0] * n.x + c[i][1] * n.y + c[i][2] * n.z));
    return out;
  }

 private:
  Vec3 apply(const Vec3& p, double w) const {
    Vec3 out;
    for (int i = 0; i < 3; ++i) out[i] = float(m[i][0] * p.x + m[i][1] * p.y + m[i][2] * p.z + m[i][3] * w);
    return out;
  }
};

inline Affine operator*(const Affine& a, const Affine& b) {
  Affine r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 4; ++j)
      r.m[i][j] = a.m[i][0] * b.m[0][j] + a.m[i][1] * b.m[1][j] + a.m[i][2] * b.m[2][j] + (j == 3 ? a.m[i][3] : 0.0);
  return r;
}

// A node's translation, rotation (unit quaternion x, y, z, w) and scale; animations replace some of them.
struct Trs {
  double t[3] = {0, 0, 0}, q[4] = {0, 0, 0, 1}, s[3] = {1, 1, 1};
};

// T * R * S. The rotation must be a unit quaternion.
inline Affine trs_affine(const Trs& trs) {
  const double x = trs.q[0], y = trs.q[1], z = trs.q[2], w = trs.q[3];
  const double r[3][3] = {{1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)},
                          {2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)},
                          {2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)}};
  Affine a;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) a.m[size_t(i)][size_t(j)] = r[i][j] * trs.s[j];
    a.m[size_t(i)][3] = trs.t[i];
  }
  return a;
}

namespace detail {
// Whether `v` is given (non-empty); wrong sizes and non-finite values are Errors naming the node.
inline bool given(const Context& c, const std::vector<double>& v, size_t n, const std::string& name, const char* field) {
  if (v.empty()) return false;
  if (v.size() != n) c.fail(name + "." + field + " has " + std::to_string(v.size()) + " numbers; expected " + std::to_string(n));
  for (double x : v)
    if (!std::isfinite(x)) c.fail(name + "." + field + " holds a NaN or infinite number");
  return true;
}
}  // namespace detail

// The node's translation, rotation (normalised) and scale, defaults where absent; its matrix is not read.
inline Trs node_trs(const Context& c, const tinygltf::Node& node, const std::string& name) {
  Trs trs;
  if (detail::given(c, node.scale, 3, name, "scale")) std::copy(node.scale.begin(), node.scale.end(), trs.s);
  if (detail::given(c, node.translation, 3, name, "translation")) std::copy(node.translation.begin(), node.translation.end(), trs.t);
  if (detail::given(c, node.rotation, 4, name, "rotation")) {
    const double len = std::sqrt(node.rotation[0] * node.rotation[0] + node.rotation[1] * node.rotation[1] +
                                 node.rotation[2] * node.rotation[2] + node.rotation[3] * node.rotation[3]);
    if (!(len > 0.0)) c.fail(name + ".rotation is a zero quaternion");
    for (int i = 0; i < 4; ++i) trs.q[i] = node.rotation[size_t(i)] / len;
  }
  return trs;
}

// The node's local transform; wrong array sizes and non-finite values are Errors naming the node.
inline Affine local_transform(const Context& c, const tinygltf::Node& node, const std::string& name) {
  if (detail::given(c, node.matrix, 16, name, "matrix")) {
    const std::vector<double>& v = node.matrix;  // column-major; the last row must be 0 0 0 1
    if (v[3] != 0.0 || v[7] != 0.0 || v[11] != 0.0 || v[15] != 1.0) c.fail(name + ".matrix is not affine (last row != 0 0 0 1)");
    Affine a;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 4; ++j) a.m[size_t(i)][size_t(j)] = v[size_t(j * 4 + i)];
    if (!node.translation.empty() || !node.rotation.empty() || !node.scale.empty()) c.warn(name + " has both matrix and TRS; matrix used");
    return a;
  }
  return trs_affine(node_trs(c, node, name));
}

}  // namespace pathspace::gltf
