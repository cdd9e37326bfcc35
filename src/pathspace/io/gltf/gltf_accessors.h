// glTF accessors read into plain arrays with every range checked: tinygltf parses the JSON and the
// buffers but does not check that accessors and buffer views stay inside their buffers, so this is
// where a malformed file must become a pathspace::Error instead of an out-of-bounds read.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "pathspace/io/gltf/gltf_context.h"

namespace pathspace::gltf {

// Accessor `index` of type `type` (TINYGLTF_TYPE_SCALAR, VEC2..4, MAT4) as floats, `components` per element:
// FLOAT components, or (for texture coordinates, `allow_normalized`) normalized unsigned byte/short.
// Non-finite values are an Error. `what` names the referring element in messages.
std::vector<float> read_floats(const Context& c, int index, int type, bool allow_normalized, const std::string& what);

// Accessor `index` of type `type` as unsigned integers (unsigned byte/short/int components: skin joints).
std::vector<uint32_t> read_unsigned(const Context& c, int index, int type, const std::string& what);

// Accessor `index` as vertex indices (SCALAR unsigned byte/short/int), each below `vertex_count`.
std::vector<uint32_t> read_indices(const Context& c, int index, size_t vertex_count, const std::string& what);

}  // namespace pathspace::gltf
