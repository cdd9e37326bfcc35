// glTF vertex skinning (see gltf_skin.h).
#include "pathspace/io/gltf/gltf_skin.h"

#include "pathspace/io/gltf/gltf_accessors.h"

namespace pathspace::gltf {

std::vector<Affine> joint_matrices(const Context& c, int skin, const std::vector<Affine>& node_world) {
  check_index(c, skin, c.model.skins.size(), "skin");
  const tinygltf::Skin& s = c.model.skins[size_t(skin)];
  const std::string name = element("skins", size_t(skin));
  std::vector<Affine> inverse_bind(s.joints.size());
  if (s.inverseBindMatrices >= 0) {
    const std::vector<float> m = read_floats(c, s.inverseBindMatrices, TINYGLTF_TYPE_MAT4, false, name + ".inverseBindMatrices");
    if (m.size() != 16 * s.joints.size())
      c.fail(name + ".inverseBindMatrices has " + std::to_string(m.size() / 16) + " matrices for " + std::to_string(s.joints.size()) + " joints");
    for (size_t j = 0; j < s.joints.size(); ++j)
      for (int row = 0; row < 3; ++row)
        for (int col = 0; col < 4; ++col) inverse_bind[j].m[size_t(row)][size_t(col)] = m[16 * j + size_t(4 * col + row)];  // column-major
  }
  std::vector<Affine> joints(s.joints.size());
  for (size_t j = 0; j < s.joints.size(); ++j) {
    check_index(c, s.joints[j], node_world.size(), name + "." + element("joints", j));
    joints[j] = node_world[size_t(s.joints[j])] * inverse_bind[j];
  }
  return joints;
}

void skin_primitive(const Context& c, const tinygltf::Primitive& p, const std::string& name, const std::vector<Affine>& joints,
                    std::vector<float>* pos, std::vector<float>* nrm) {
  const auto joints_it = p.attributes.find("JOINTS_0"), weights_it = p.attributes.find("WEIGHTS_0");
  if (joints_it == p.attributes.end() || weights_it == p.attributes.end()) c.fail(name + " belongs to a skinned node but has no JOINTS_0 and WEIGHTS_0");
  const std::vector<uint32_t> joint = read_unsigned(c, joints_it->second, TINYGLTF_TYPE_VEC4, name + ".attributes.JOINTS_0");
  const std::vector<float> weight = read_floats(c, weights_it->second, TINYGLTF_TYPE_VEC4, true, name + ".attributes.WEIGHTS_0");
  const size_t n = pos->size() / 3;
  if (joint.size() != 4 * n || weight.size() != 4 * n) c.fail(name + ": JOINTS_0 and WEIGHTS_0 must have one element per vertex");
  for (size_t v = 0; v < n; ++v) {
    Affine blend;
    for (auto& row : blend.m) row.fill(0.0);
    double total = 0.0;
    for (size_t i = 0; i < 4; ++i) {
      const double w = weight[4 * v + i];
      if (w == 0.0) continue;
      if (joint[4 * v + i] >= joints.size())
        c.fail(name + ": vertex " + std::to_string(v) + " names joint " + std::to_string(joint[4 * v + i]) + " of " + std::to_string(joints.size()));
      const Affine& m = joints[joint[4 * v + i]];
      for (size_t r = 0; r < 3; ++r)
        for (size_t k = 0; k < 4; ++k) blend.m[r][k] += w * m.m[r][k];
      total += w;
    }
    if (!(total > 0.0)) continue;  // no influence (the spec wants weights summing to 1): left in bind space
    const Vec3 p3 = blend.point(Vec3((*pos)[3 * v], (*pos)[3 * v + 1], (*pos)[3 * v + 2]));
    for (int k = 0; k < 3; ++k) (*pos)[3 * v + size_t(k)] = p3[k];
    if (!nrm->empty()) {
      const Vec3 n3 = blend.normal(Vec3((*nrm)[3 * v], (*nrm)[3 * v + 1], (*nrm)[3 * v + 2]));
      for (int k = 0; k < 3; ++k) (*nrm)[3 * v + size_t(k)] = n3[k];
    }
  }
}

}  // namespace pathspace::gltf
