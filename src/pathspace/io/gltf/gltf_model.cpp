// Reading a glTF file into tinygltf's model (see gltf_model.h).
#include "pathspace/io/gltf/gltf_model.h"

#include <algorithm>
#include <filesystem>
#include <set>
#include <sstream>

#include "pathspace/io/file_bytes.h"
#include "pathspace/io/gltf/gltf_context.h"
#include "pathspace/io/gltf/gltf_json_check.h"

namespace pathspace::gltf {

namespace {

// tinygltf image callback: keep the encoded bytes; io/image_io decodes them per material slot. A
// bufferView image is passed as &buffer[byteOffset] with byteLength unchecked by tinygltf, so the
// range is checked here before any byte is read.
bool keep_image_bytes(tinygltf::Image* image, const int index, std::string* err, std::string*, int, int, const unsigned char* bytes,
                      int size, void* user) {
  const auto* model = static_cast<const tinygltf::Model*>(user);
  if (image->bufferView >= 0) {
    const tinygltf::BufferView& v = model->bufferViews.at(size_t(image->bufferView));
    const size_t have = model->buffers.at(size_t(v.buffer)).data.size();
    if (v.byteOffset > have || v.byteLength > have - v.byteOffset) {
      if (err) *err += "images[" + std::to_string(index) + "]: its bufferView lies outside its buffer\n";
      return false;
    }
  }
  if (size < 0) return false;
  image->image.assign(bytes, bytes + size);
  image->as_is = true;
  return true;
}

// External buffers and images, read through read_file_as_stored: a FIFO or device named by a
// uri is refused instead of blocking or filling memory (tinygltf's own reader opens anything).
bool read_referenced_file(std::vector<unsigned char>* out, std::string* err, const std::string& path, void*) {
  try {
    const std::string bytes = read_file_as_stored(path);
    out->assign(bytes.begin(), bytes.end());
    return true;
  } catch (const Error& e) {
    *err += std::string(e.what()) + "\n";
    return false;
  }
}

// Whether a referenced file exists, without opening it (tinygltf's own check opens it, which waits
// for a writer when it is a FIFO).
bool referenced_file_exists(const std::string& path, void*) {
  std::error_code ec;
  return std::filesystem::exists(path, ec);
}

void parse(const std::string& path, tinygltf::Model* model, LoadWarnings* w) {
  const std::string bytes = read_file_bytes(path);
  check_gltf_json(path, bytes);
  tinygltf::TinyGLTF loader;
  loader.SetFsCallbacks(tinygltf::FsCallbacks{&referenced_file_exists, &tinygltf::ExpandFilePath, &read_referenced_file,
                                              &tinygltf::WriteWholeFile, nullptr});
  loader.SetImageLoader(keep_image_bytes, model);
  std::string err, warn;
  const std::string folder = std::filesystem::path(path).parent_path().string();
  const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
  const bool ok = bytes.size() >= 4 && bytes.compare(0, 4, "glTF") == 0
                      ? loader.LoadBinaryFromMemory(model, &err, &warn, data, unsigned(std::min<size_t>(bytes.size(), UINT32_MAX)), folder)
                      : loader.LoadASCIIFromString(model, &err, &warn, bytes.data(), unsigned(std::min<size_t>(bytes.size(), UINT32_MAX)), folder);
  std::string line;
  for (std::istringstream ws(warn); std::getline(ws, line);)
    if (!line.empty()) w->add(FileLoc{path}, "tinygltf: " + line);
  if (!ok || !err.empty()) {
    while (!err.empty() && err.back() == '\n') err.pop_back();
    throw Error(FileLoc{path}, "cannot read glTF: " + (err.empty() ? std::string("parse failed") : err));
  }
}

void check_extensions(const Context& c) {
  static const std::set<std::string> kSupported = {"KHR_lights_punctual", "KHR_materials_emissive_strength", "KHR_materials_transmission",
                                                   "KHR_materials_ior"};
  for (const std::string& e : c.model.extensionsRequired)
    if (!kSupported.count(e)) c.fail("extensionsRequired: " + e + " is not supported");
  for (const std::string& e : c.model.extensionsUsed)
    if (!kSupported.count(e)) c.warn("extensionsUsed: " + e + " is not supported; ignored");
}

}  // namespace

void read_model(const std::string& path, tinygltf::Model* model, LoadWarnings* warnings) {
  parse(path, model, warnings);
  check_extensions(Context{*model, path, std::filesystem::path(path).parent_path().string(), warnings});
}

}  // namespace pathspace::gltf
