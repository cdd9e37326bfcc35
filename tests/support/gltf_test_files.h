// Writing small glTF files from tests: a GltfBuilder collects binary data into one buffer with
// bufferViews and accessors, and emits a .gltf (JSON with a base64 data-uri buffer) or a .glb
// (JSON chunk + BIN chunk) around the caller's JSON for scenes, nodes, meshes and materials.
#pragma once

#include <cstdint>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

#include "pathspace/base/base64.h"

namespace pathspace::testing {

inline std::string base64(const std::string& bytes) { return base64_encode(bytes); }

inline void write_bytes(const std::string& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), std::streamsize(bytes.size()));
}

class GltfBuilder {
 public:
  // An accessor of float elements ("VEC2", "VEC3", ...); returns its index.
  int floats(const std::vector<float>& v, const std::string& type) { return add(v.data(), v.size() * 4, 5126, type, count_of(v.size(), type)); }
  // An accessor of unsigned int indices.
  int indices(const std::vector<uint32_t>& v) { return add(v.data(), v.size() * 4, 5125, "SCALAR", v.size()); }
  // An accessor of unsigned int elements ("VEC4": skin joints).
  int uints(const std::vector<uint32_t>& v, const std::string& type) { return add(v.data(), v.size() * 4, 5125, type, count_of(v.size(), type)); }
  // A bufferView holding raw bytes (an embedded image); returns the view's index.
  int view(const std::string& bytes) { return add_view(bytes.data(), bytes.size()); }

  // The .gltf text: `rest` holds the other top-level members (without braces), e.g. "\"nodes\": [...]".
  std::string gltf(const std::string& rest) const {
    return head() + ",\"buffers\":[{\"byteLength\":" + std::to_string(data_.size()) + ",\"uri\":\"data:application/octet-stream;base64," +
           base64(data_) + "\"}]" + (rest.empty() ? "" : "," + rest) + "}";
  }
  // The same scene as .glb bytes (the buffer is the BIN chunk).
  std::string glb(const std::string& rest) const {
    std::string json = head() + ",\"buffers\":[{\"byteLength\":" + std::to_string(data_.size()) + "}]" + (rest.empty() ? "" : "," + rest) + "}";
    while (json.size() % 4) json += ' ';
    std::string bin = data_;
    while (bin.size() % 4) bin += '\0';
    std::string out = "glTF";
    u32(&out, 2);
    u32(&out, uint32_t(12 + 8 + json.size() + 8 + bin.size()));
    u32(&out, uint32_t(json.size()));
    out += "JSON" + json;
    u32(&out, uint32_t(bin.size()));
    out += std::string("BIN\0", 4) + bin;
    return out;
  }

 private:
  static size_t count_of(size_t n, const std::string& type) {
    return type == "VEC2" ? n / 2 : type == "VEC3" ? n / 3 : type == "VEC4" ? n / 4 : type == "MAT4" ? n / 16 : n;
  }
  static void u32(std::string* s, uint32_t v) { s->append(reinterpret_cast<const char*>(&v), 4); }
  int add_view(const void* p, size_t bytes) {
    while (data_.size() % 4) data_ += '\0';
    views_ += std::string(views_.empty() ? "" : ",") + "{\"buffer\":0,\"byteOffset\":" + std::to_string(data_.size()) +
              ",\"byteLength\":" + std::to_string(bytes) + "}";
    data_.append(static_cast<const char*>(p), bytes);
    return num_views_++;
  }
  int add(const void* p, size_t bytes, int component, const std::string& type, size_t count) {
    const int v = add_view(p, bytes);
    accessors_ += std::string(accessors_.empty() ? "" : ",") + "{\"bufferView\":" + std::to_string(v) +
                  ",\"componentType\":" + std::to_string(component) + ",\"count\":" + std::to_string(count) + ",\"type\":\"" + type + "\"}";
    return num_accessors_++;
  }
  std::string head() const {
    return "{\"asset\":{\"version\":\"2.0\"},\"bufferViews\":[" + views_ + "],\"accessors\":[" + accessors_ + "]";
  }

  std::string data_, views_, accessors_;
  int num_views_ = 0, num_accessors_ = 0;
};

}  // namespace pathspace::testing
