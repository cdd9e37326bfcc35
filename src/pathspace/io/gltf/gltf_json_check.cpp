#include "pathspace/io/gltf/gltf_json_check.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <cstring>
#include <string_view>

#include "pathspace/base/error.h"

namespace pathspace::gltf {

namespace {

// A SAX handler that only counts nesting (no document is built, so no recursion anywhere).
struct DepthLimit : nlohmann::json_sax<nlohmann::json> {
  int depth = 0;
  bool too_deep = false;
  bool open() {
    too_deep = too_deep || ++depth > kMaxJsonDepth;
    return !too_deep;
  }
  bool null() override { return true; }
  bool boolean(bool) override { return true; }
  bool number_integer(number_integer_t) override { return true; }
  bool number_unsigned(number_unsigned_t) override { return true; }
  bool number_float(number_float_t, const string_t&) override { return true; }
  bool string(string_t&) override { return true; }
  bool binary(binary_t&) override { return true; }
  bool start_object(std::size_t) override { return open(); }
  bool key(string_t&) override { return true; }
  bool end_object() override { return --depth, true; }
  bool start_array(std::size_t) override { return open(); }
  bool end_array() override { return --depth, true; }
  bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception&) override { return false; }
};

uint32_t le32(const std::string& b, size_t at) {
  uint32_t v = 0;
  std::memcpy(&v, b.data() + at, 4);  // glTF binary is little-endian, as every platform pathspace runs on
  return v;
}

// The JSON text: the whole file, or a .glb's first chunk (12-byte header, then length and type).
std::string_view json_text(const std::string& bytes) {
  if (bytes.size() < 20 || bytes.compare(0, 4, "glTF") != 0) return bytes;
  const uint32_t length = le32(bytes, 12);
  if (bytes.compare(16, 4, "JSON") != 0 || length > bytes.size() - 20) return {};  // tinygltf reports it
  return std::string_view(bytes).substr(20, length);
}

}  // namespace

void check_gltf_json(const std::string& path, const std::string& bytes) {
  const std::string_view text = json_text(bytes);
  DepthLimit limit;
  if (nlohmann::json::sax_parse(text.begin(), text.end(), &limit, nlohmann::json::input_format_t::json, false)) {
    // Bounded in depth now: a document can be built. Syntax errors are tinygltf's to report.
    const nlohmann::json j = nlohmann::json::parse(text.begin(), text.end(), nullptr, false);
    if (j.is_object() && j.contains("cameras") && j["cameras"].is_array())
      for (size_t i = 0; i < j["cameras"].size(); ++i) {
        const nlohmann::json& c = j["cameras"][i];
        if (!c.is_object() || !c.contains("perspective") || !c["perspective"].is_object()) continue;
        const nlohmann::json& p = c["perspective"];
        if (p.contains("aspectRatio") && !(p["aspectRatio"].is_number() && p["aspectRatio"].get<double>() > 0.0))
          throw Error(FileLoc{path}, "cameras[" + std::to_string(i) + "].perspective.aspectRatio must be a number > 0, not " +
                                         p["aspectRatio"].dump());
      }
  }
  if (limit.too_deep)
    throw Error(FileLoc{path}, "the JSON nests arrays and objects more than " + std::to_string(kMaxJsonDepth) + " deep");
}

}  // namespace pathspace::gltf
