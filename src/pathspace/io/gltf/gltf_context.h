// What every part of the glTF loader shares: the parsed model, the file (for messages and relative
// image paths) and the warning list. glTF has no line numbers after parsing, so messages name the
// element instead ("materials[3].occlusionTexture ignored").
#pragma once

#include <string>

#include "pathspace/base/error.h"
#include "pathspace/io/gltf/tinygltf.h"
#include "pathspace/io/load_warnings.h"

namespace pathspace::gltf {

struct Context {
  const tinygltf::Model& model;
  std::string path;    // the .gltf/.glb file
  std::string folder;  // where relative uris point
  LoadWarnings* warnings;

  void warn(const std::string& message) const { warnings->add(FileLoc{path}, message); }
  [[noreturn]] void fail(const std::string& message) const { throw Error(FileLoc{path}, message); }
};

// "name[i]" for messages.
inline std::string element(const char* array, size_t i) { return std::string(array) + "[" + std::to_string(i) + "]"; }

// Checks that `index` names an entry of a model array of `size` entries (Error otherwise).
inline void check_index(const Context& c, int index, size_t size, const std::string& what) {
  if (index < 0 || size_t(index) >= size)
    c.fail(what + " = " + std::to_string(index) + " names nothing (" + std::to_string(size) + " defined)");
}

}  // namespace pathspace::gltf
