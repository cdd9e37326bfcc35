// glTF mesh primitives (see gltf_meshes.h). A mirroring transform (negative determinant) reverses
// the winding, as the glTF spec requires, so that front faces stay front faces.
#include "pathspace/io/gltf/gltf_meshes.h"

#include <cmath>
#include <set>

#include "pathspace/io/gltf/gltf_accessors.h"
#include "pathspace/io/gltf/gltf_skin.h"

namespace pathspace::gltf {

namespace {

int attribute(const tinygltf::Primitive& p, const char* name) {
  const auto it = p.attributes.find(name);
  return it == p.attributes.end() ? -1 : it->second;
}

// pos (and nrm, when not empty) displaced by the morph targets' POSITION and NORMAL deltas times their weights.
void blend_morph_targets(const Context& c, const tinygltf::Primitive& p, const std::string& name, const std::vector<double>& weights,
                         std::vector<float>* pos, std::vector<float>* nrm) {
  for (size_t k = 0; k < p.targets.size() && k < weights.size(); ++k) {
    const std::string target = name + "." + element("targets", k);
    for (const auto& [attr, accessor] : p.targets[k]) {
      std::vector<float>* base = attr == "POSITION" ? pos : attr == "NORMAL" ? nrm : nullptr;
      if (!base) continue;  // reported once, by morph_target_count
      const std::vector<float> delta = read_floats(c, accessor, TINYGLTF_TYPE_VEC3, false, target + "." + attr);
      if (delta.size() != pos->size()) c.fail(target + "." + attr + " count differs from POSITION's");
      if (base->empty() || weights[k] == 0.0) continue;
      for (size_t i = 0; i < base->size(); ++i) (*base)[i] += float(weights[k] * double(delta[i]));
    }
  }
}

void add_primitive(const Context& c, const tinygltf::Primitive& p, const std::string& name, const Affine& world_of_node,
                   const std::vector<double>& weights, const std::vector<Affine>* joints, Materials* materials, Scene* scene) {
  const int mode = p.mode < 0 ? TINYGLTF_MODE_TRIANGLES : p.mode;
  if (mode != TINYGLTF_MODE_TRIANGLES) {
    c.warn(name + ".mode " + std::to_string(mode) + " (points, lines, strips or fans) not supported; primitive skipped");
    return;
  }
  for (const auto& [attr, accessor] : p.attributes)
    if (attr != "POSITION" && attr != "NORMAL" && attr != "TEXCOORD_0" && !(joints && (attr == "JOINTS_0" || attr == "WEIGHTS_0")))
      c.warn(name + ".attributes." + attr + " ignored");
  const int pos_index = attribute(p, "POSITION");
  if (pos_index < 0) c.fail(name + " has no POSITION attribute");
  std::vector<float> pos = read_floats(c, pos_index, TINYGLTF_TYPE_VEC3, false, name + ".attributes.POSITION");
  const size_t n = pos.size() / 3;
  std::vector<float> nrm, uv;
  if (const int i = attribute(p, "NORMAL"); i >= 0) nrm = read_floats(c, i, TINYGLTF_TYPE_VEC3, false, name + ".attributes.NORMAL");
  if (const int i = attribute(p, "TEXCOORD_0"); i >= 0) uv = read_floats(c, i, TINYGLTF_TYPE_VEC2, true, name + ".attributes.TEXCOORD_0");
  if (!nrm.empty() && nrm.size() != 3 * n) c.fail(name + ".attributes.NORMAL count differs from POSITION's");
  if (!uv.empty() && uv.size() != 2 * n) c.fail(name + ".attributes.TEXCOORD_0 count differs from POSITION's");
  blend_morph_targets(c, p, name, weights, &pos, &nrm);
  // A skinned mesh is in world space once skinned: the node's transform does not apply.
  if (joints) skin_primitive(c, p, name, *joints, &pos, &nrm);
  const Affine world = joints ? Affine() : world_of_node;

  std::vector<uint32_t> indices;
  if (p.indices >= 0) {
    indices = read_indices(c, p.indices, n, name + ".indices");
  } else {
    indices.resize(n);
    for (size_t i = 0; i < n; ++i) indices[i] = uint32_t(i);
  }
  if (indices.size() % 3 != 0) c.warn(name + ": " + std::to_string(indices.size()) + " vertices is not a multiple of 3; the last ones are dropped");
  if (indices.size() < 3) return;

  const Surface surface = materials->get(p.material, name + ".material");
  const uint32_t base = uint32_t(scene->positions.size());
  if (size_t(base) + n > size_t(UINT32_MAX)) c.fail(name + ": too many vertices in the scene");
  for (size_t i = 0; i < n; ++i) scene->positions.push_back(world.point(Vec3(pos[3 * i], pos[3 * i + 1], pos[3 * i + 2])));
  if (!nrm.empty()) {  // smooth shading normals; a zero or degenerate one means flat shading there
    scene->normals.resize(base);
    for (size_t i = 0; i < n; ++i) {
      const Vec3 w = world.normal(Vec3(nrm[3 * i], nrm[3 * i + 1], nrm[3 * i + 2]));
      scene->normals.push_back(length(w) > 0.f && all_finite(normalize(w)) ? normalize(w) : Vec3());
    }
  }
  if (!uv.empty()) {
    scene->uvs.resize(base);
    for (size_t i = 0; i < n; ++i) scene->uvs.push_back(Point2{uv[2 * i], 1.f - uv[2 * i + 1]});  // glTF v = 0 is the top row
  }
  const bool mirrored = world.determinant() < 0.0;
  const bool emits = !is_black(surface.emission);
  for (size_t t = 0; t + 2 < indices.size(); t += 3) {
    const uint32_t a = base + indices[t], b = base + indices[t + (mirrored ? 2 : 1)], d = base + indices[t + (mirrored ? 1 : 2)];
    const Vec3 ng = cross(scene->positions[b] - scene->positions[a], scene->positions[d] - scene->positions[a]);
    if (emits && !(length(ng) > 0.f)) continue;  // a zero-area emitter cannot be sampled
    Triangle tri{{a, b, d}, surface.material, kNoLight};
    if (emits) {
      Light l;
      l.type = LightType::area_triangle;
      l.shape = uint32_t(scene->triangles.size());
      l.value = surface.emission;
      l.texture = surface.emission_texture;
      l.two_sided = surface.two_sided;
      tri.light = int32_t(scene->lights.size());
      scene->lights.push_back(l);
    }
    scene->triangles.push_back(tri);
  }
}

}  // namespace

size_t morph_target_count(const Context& c, int mesh_index) {
  const std::string name = element("meshes", size_t(mesh_index));
  const tinygltf::Mesh& mesh = c.model.meshes[size_t(mesh_index)];
  const size_t targets = mesh.primitives.empty() ? 0 : mesh.primitives[0].targets.size();
  for (size_t i = 0; i < mesh.primitives.size(); ++i) {
    const tinygltf::Primitive& p = mesh.primitives[i];
    const std::string prim = name + "." + element("primitives", i);
    if (p.targets.size() != targets)
      c.fail(prim + " has " + std::to_string(p.targets.size()) + " morph targets, primitives[0] " + std::to_string(targets) +
             " (the glTF spec wants as many in every primitive)");
  }
  if (!mesh.weights.empty() && mesh.weights.size() != targets)
    c.fail(name + ".weights has " + std::to_string(mesh.weights.size()) + " values for " + std::to_string(targets) + " morph targets");
  return targets;
}

std::vector<double> default_morph_weights(const Context& c, const tinygltf::Node& node, const std::string& node_name) {
  const size_t targets = morph_target_count(c, node.mesh);
  const tinygltf::Mesh& mesh = c.model.meshes[size_t(node.mesh)];
  for (size_t i = 0; i < mesh.primitives.size(); ++i)
    for (size_t k = 0; k < mesh.primitives[i].targets.size(); ++k)
      for (const auto& [attr, accessor] : mesh.primitives[i].targets[k])
        if (attr != "POSITION" && attr != "NORMAL")
          c.warn(element("meshes", size_t(node.mesh)) + "." + element("primitives", i) + "." + element("targets", k) + "." + attr +
                 " ignored");
  if (!node.weights.empty() && node.weights.size() != targets)
    c.fail(node_name + ".weights has " + std::to_string(node.weights.size()) + " values for " + std::to_string(targets) +
           " morph targets of its mesh");
  std::vector<double> w = !node.weights.empty() ? node.weights : mesh.weights;
  w.resize(targets, 0.0);
  for (double x : w)
    if (!std::isfinite(x)) c.fail(node_name + ": a morph weight is not finite");
  return w;
}

void add_mesh(const Context& c, int mesh_index, const Affine& world, const std::vector<double>& weights,
              const std::vector<Affine>* joints, Materials* materials, Scene* scene) {
  const std::string name = element("meshes", size_t(mesh_index));
  const tinygltf::Mesh& mesh = c.model.meshes[size_t(mesh_index)];
  for (size_t i = 0; i < mesh.primitives.size(); ++i)
    add_primitive(c, mesh.primitives[i], name + "." + element("primitives", i), world, weights, joints, materials, scene);
}

}  // namespace pathspace::gltf
