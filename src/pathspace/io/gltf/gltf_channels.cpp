// Reading and checking node animation channels (see gltf_channels.h).
#include "pathspace/io/gltf/gltf_channels.h"

#include <cmath>
#include <set>
#include <sstream>
#include <utility>

#include "pathspace/io/gltf/gltf_accessors.h"
#include "pathspace/io/gltf/gltf_meshes.h"

namespace pathspace::gltf {

namespace {

Interpolation interpolation_of(const Context& c, const std::string& text, const std::string& what) {
  if (text == "LINEAR") return Interpolation::linear;
  if (text == "STEP") return Interpolation::step;
  if (text == "CUBICSPLINE") return Interpolation::cubic_spline;
  c.fail(what + ".interpolation '" + text + "' is not LINEAR, STEP or CUBICSPLINE");
}

std::vector<double> to_double(const std::vector<float>& v) { return std::vector<double>(v.begin(), v.end()); }

std::string seconds(double t) {
  std::ostringstream o;
  o << t << " s";
  return o.str();
}

void check_times(const Context& c, const std::vector<double>& times, const std::string& what) {
  if (times.empty()) c.fail(what + " has no keys");
  if (!(times[0] >= 0.0)) c.fail(what + ": key time " + seconds(times[0]) + " is negative");
  for (size_t k = 1; k < times.size(); ++k)
    if (!(times[k] > times[k - 1]))
      c.fail(what + ": key times must increase strictly (key " + std::to_string(k) + " at " + seconds(times[k]) + " follows " +
             seconds(times[k - 1]) + ")");
}

// Rotation keys are normalised here (slerp needs unit quaternions); a zero one has no direction.
void normalize_rotations(const Context& c, Channel* ch) {
  for (size_t i = 0; i < ch->values.size(); i += 4) {
    // CUBICSPLINE tangents are derivatives, not rotations: only the values are normalised.
    if (ch->interpolation == Interpolation::cubic_spline && (i / 4) % 3 != 1) continue;
    double* q = &ch->values[i];
    const double len = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    if (!(len > 0.0)) c.fail(ch->name + ": rotation key " + std::to_string(i / 4) + " is a zero quaternion");
    for (int k = 0; k < 4; ++k) q[k] /= len;
  }
}

}  // namespace

std::vector<Channel> read_channels(const Context& c, size_t animation) {
  const tinygltf::Animation& a = c.model.animations.at(animation);
  const std::string anim = element("animations", animation);
  std::vector<Channel> out;
  std::set<std::pair<int, AnimatedProperty>> targets;
  for (size_t i = 0; i < a.channels.size(); ++i) {
    const tinygltf::AnimationChannel& ac = a.channels[i];
    Channel ch;
    ch.name = anim + "." + element("channels", i);
    const std::string& path = ac.target_path;
    if (path == "translation") ch.property = AnimatedProperty::translation;
    else if (path == "rotation") ch.property = AnimatedProperty::rotation;
    else if (path == "scale") ch.property = AnimatedProperty::scale;
    else if (path == "weights") ch.property = AnimatedProperty::weights;
    else {
      c.warn(ch.name + ".target.path '" + path + "' not supported (unknown path); channel skipped");
      continue;
    }
    check_index(c, ac.target_node, c.model.nodes.size(), ch.name + ".target.node");
    ch.node = ac.target_node;
    const std::string node = element("nodes", size_t(ch.node));
    const tinygltf::Node& target = c.model.nodes[size_t(ch.node)];
    if (ch.property == AnimatedProperty::weights) {
      if (target.mesh < 0) c.fail(ch.name + " animates the morph weights of " + node + ", which has no mesh");
      check_index(c, target.mesh, c.model.meshes.size(), node + ".mesh");
      ch.targets = morph_target_count(c, target.mesh);
      if (ch.targets == 0) c.fail(ch.name + " animates the morph weights of " + node + ", whose mesh has no morph targets");
    } else if (!target.matrix.empty()) {
      c.fail(ch.name + " animates " + node + ", which has a matrix (glTF allows TRS only)");
    }
    if (!targets.insert({ch.node, ch.property}).second) c.fail(ch.name + ": " + node + "." + path + " is animated twice in " + anim);

    check_index(c, ac.sampler, a.samplers.size(), ch.name + ".sampler");
    const tinygltf::AnimationSampler& s = a.samplers[size_t(ac.sampler)];
    const std::string sampler = anim + "." + element("samplers", size_t(ac.sampler));
    ch.interpolation = interpolation_of(c, s.interpolation, sampler);
    ch.times = to_double(read_floats(c, s.input, TINYGLTF_TYPE_SCALAR, false, sampler + ".input"));
    check_times(c, ch.times, sampler + ".input");
    const int type = ch.property == AnimatedProperty::rotation  ? TINYGLTF_TYPE_VEC4
                     : ch.property == AnimatedProperty::weights ? TINYGLTF_TYPE_SCALAR
                                                                : TINYGLTF_TYPE_VEC3;
    // Rotations and weights may be stored as normalized integers (the glTF spec); read_floats takes the unsigned ones.
    const bool normalized = ch.property == AnimatedProperty::rotation || ch.property == AnimatedProperty::weights;
    ch.values = to_double(read_floats(c, s.output, type, normalized, sampler + ".output"));
    const size_t per_key = ch.interpolation == Interpolation::cubic_spline ? 3 : 1;
    const size_t have = ch.values.size() / ch.components(), want = ch.times.size() * per_key;
    if (have != want || ch.values.size() % ch.components() != 0)
      c.fail(sampler + ".output has " + std::to_string(have) + " values for " + std::to_string(ch.times.size()) + " key times; expected " +
             std::to_string(want) + (per_key == 3 ? " (CUBICSPLINE: in-tangent, value, out-tangent per key)" : ""));
    if (ch.property == AnimatedProperty::rotation) normalize_rotations(c, &ch);
    out.push_back(std::move(ch));
  }
  return out;
}

}  // namespace pathspace::gltf
