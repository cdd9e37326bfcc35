// glTF textures and images (see gltf_textures.h).
#include "pathspace/io/gltf/gltf_textures.h"

#include "pathspace/base/regular_file.h"
#include "pathspace/io/texture_file.h"

#include <filesystem>

namespace pathspace::gltf {

namespace {

// glTF uris are URI references: %XX escapes are decoded, the rest is a path relative to the file.
std::string decode_uri(const std::string& uri) {
  std::string out;
  for (size_t i = 0; i < uri.size(); ++i) {
    auto hex = [](char ch) { return ch >= '0' && ch <= '9' ? ch - '0' : ch >= 'a' && ch <= 'f' ? ch - 'a' + 10 : ch >= 'A' && ch <= 'F' ? ch - 'A' + 10 : -1; };
    if (uri[i] == '%' && i + 2 < uri.size() && hex(uri[i + 1]) >= 0 && hex(uri[i + 2]) >= 0) {
      out.push_back(char(hex(uri[i + 1]) * 16 + hex(uri[i + 2])));
      i += 2;
    } else {
      out.push_back(uri[i]);
    }
  }
  return out;
}

// A sampler's addressing and magnification (no MIP maps: minFilter is not used).
void apply_sampler(const tinygltf::Model& m, const tinygltf::Texture& t, ImageTexture* out) {
  if (t.sampler < 0 || size_t(t.sampler) >= m.samplers.size()) return;  // glTF's default: repeat, linear
  const tinygltf::Sampler& s = m.samplers[size_t(t.sampler)];
  out->wrap = s.wrapS == TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE     ? TextureWrap::clamp
              : s.wrapS == TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT ? TextureWrap::mirror
                                                                 : TextureWrap::repeat;
  out->nearest = s.magFilter == TINYGLTF_TEXTURE_FILTER_NEAREST;
}

}  // namespace

std::optional<Textures::Encoded> Textures::encoded(int texture_index) {
  const tinygltf::Model& m = c_.model;
  const std::string tname = element("textures", size_t(texture_index));
  const tinygltf::Texture& t = m.textures[size_t(texture_index)];
  if (t.sampler >= 0) {
    check_index(c_, t.sampler, m.samplers.size(), tname + ".sampler");
    const tinygltf::Sampler& s = m.samplers[size_t(t.sampler)];
    if (s.wrapS != s.wrapT)
      c_.warn(element("samplers", size_t(t.sampler)) + ": wrapS and wrapT differ; wrapS is used for both (one mode a texture)");
  }
  if (t.source < 0) {
    c_.warn(tname + " has no source image (image extensions such as KHR_texture_basisu are not supported); constant factor used");
    return std::nullopt;
  }
  check_index(c_, t.source, m.images.size(), tname + ".source");
  const tinygltf::Image& im = m.images[size_t(t.source)];
  const std::string iname = element("images", size_t(t.source));
  try {
    if (!im.image.empty())  // embedded (data uri or bufferView): bytes kept by the load callback
      return Encoded{c_.path + " " + iname, iname, std::string(im.image.begin(), im.image.end())};
    if (!im.uri.empty()) {
      std::filesystem::path file(decode_uri(im.uri));
      if (file.is_relative()) file = std::filesystem::path(c_.folder) / file;
      return Encoded{file.string(), iname, read_file_as_stored(file.string())};
    }
    c_.warn(iname + " holds no data; constant factor used");
  } catch (const Error& e) {
    c_.warn(iname + " not used (" + e.what() + "); constant factor used");
  }
  return std::nullopt;
}

std::optional<Image> Textures::decoded(const Encoded& e, LdrEncoding ldr) {
  try {
    Image image = decode_image(e.name, e.bytes, ldr);
    if (image.width > 0 && image.height > 0) return image;
  } catch (const Error& err) {
    c_.warn(e.element + " not used (" + err.what() + "); constant factor used");
  }
  return std::nullopt;
}

bool Textures::decoded_bytes(const Encoded& e, std::optional<ByteImage>* out) {
  try {
    *out = decode_image_bytes(e.name, e.bytes);
    return true;
  } catch (const Error& err) {
    c_.warn(e.element + " not used (" + err.what() + "); constant factor used");
    return false;
  }
}

int32_t Textures::texture(const tinygltf::TextureInfo& info, LdrEncoding ldr, const std::string& what) {
  if (info.texCoord != 0) c_.warn(what + ".texCoord = " + std::to_string(info.texCoord) + " not supported; TEXCOORD_0 used");
  if (info.extensions.count("KHR_texture_transform")) c_.warn(what + ".extensions.KHR_texture_transform ignored");
  const auto key = std::make_pair(info.index, ldr);
  if (const auto it = scene_textures_.find(key); it != scene_textures_.end()) return it->second;
  check_index(c_, info.index, c_.model.textures.size(), what + ".index");
  int32_t& index = scene_textures_[key] = -1;
  const std::optional<Encoded> e = encoded(info.index);
  if (!e) return index;
  ImageTexture t;
  t.name = c_.path + " " + element("textures", size_t(info.index));
  apply_sampler(c_.model, c_.model.textures[size_t(info.index)], &t);
  // An 8-bit image stays 8-bit (scene/image_texture.h), decoded without a float image in between.
  std::optional<ByteImage> bytes;
  if (!decoded_bytes(*e, &bytes)) return index;
  if (bytes) {
    take_texels(&t, std::move(*bytes), ldr);
  } else {
    std::optional<Image> image = decoded(*e, ldr);
    if (!image) return index;
    take_texels(&t, std::move(*image));
  }
  return index = int32_t(scene_->add_texture(std::move(t)));
}

std::optional<Rgb> Textures::mean(int texture_index, LdrEncoding ldr, const std::string& what) {
  check_index(c_, texture_index, c_.model.textures.size(), what + ".index");
  const auto key = std::make_pair(texture_index, ldr);
  if (const auto it = means_.find(key); it != means_.end()) return it->second;
  std::optional<Rgb>& mean = means_[key];
  const std::optional<Encoded> e = encoded(texture_index);
  if (!e) return mean;
  // An 8-bit image is averaged through its bytes' table: no float image in memory.
  std::optional<ByteImage> bytes;
  if (!decoded_bytes(*e, &bytes)) return mean;
  Rgb sum;
  size_t n = 0;
  if (bytes) {
    const float* value = byte_values(ldr);
    n = bytes->rgb.size() / 3;
    for (size_t i = 0; i < n; ++i) sum += Rgb(value[bytes->rgb[3 * i]], value[bytes->rgb[3 * i + 1]], value[bytes->rgb[3 * i + 2]]);
  } else {
    const std::optional<Image> image = decoded(*e, ldr);
    if (!image) return mean;
    n = image->pixels.size();
    for (const Rgb& p : image->pixels) sum += p;
  }
  return mean = sum * (1.f / float(n));
}

}  // namespace pathspace::gltf
