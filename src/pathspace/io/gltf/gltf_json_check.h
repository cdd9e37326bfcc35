// What tinygltf does not check in a glTF file's JSON, checked before it parses: nesting depth
// (tinygltf turns extras and extensions into its own values recursively, so a file of deeply nested
// arrays overflows the stack) and values that tinygltf cannot tell from absent (a camera's
// aspectRatio of 0 reads as "none given").
#pragma once

#include <string>

namespace pathspace::gltf {

// Deepest nesting of arrays and objects accepted; real glTF files stay below 20.
inline constexpr int kMaxJsonDepth = 128;

// `bytes` is the whole .gltf or .glb file. Throws pathspace::Error naming `path`.
void check_gltf_json(const std::string& path, const std::string& bytes);

}  // namespace pathspace::gltf
