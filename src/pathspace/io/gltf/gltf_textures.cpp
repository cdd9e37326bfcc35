// glTF textures and images (see gltf_textures.h).
#include "pathspace/io/gltf/gltf_textures.h"

#include "pathspace/scene/texture_bytes.h"

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

const Image* Textures::image(int texture_index, LdrEncoding ldr, const std::string& what) {
  const tinygltf::Model& m = c_.model;
  check_index(c_, texture_index, m.textures.size(), what + ".index");
  const auto key = std::make_pair(texture_index, ldr);
  if (const auto it = images_.find(key); it != images_.end()) return it->second ? &*it->second : nullptr;
  std::optional<Image>& slot = images_[key];
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
    return nullptr;
  }
  check_index(c_, t.source, m.images.size(), tname + ".source");
  const tinygltf::Image& im = m.images[size_t(t.source)];
  const std::string iname = element("images", size_t(t.source));
  try {
    if (!im.image.empty()) {  // embedded (data uri or bufferView): bytes kept by the load callback
      slot = decode_image(c_.path + " " + iname, std::string(im.image.begin(), im.image.end()), ldr);
    } else if (!im.uri.empty()) {
      std::filesystem::path file(decode_uri(im.uri));
      if (file.is_relative()) file = std::filesystem::path(c_.folder) / file;
      slot = read_image(file.string(), ldr);
    } else {
      c_.warn(iname + " holds no data; constant factor used");
    }
  } catch (const Error& e) {
    c_.warn(iname + " not used (" + e.what() + "); constant factor used");
  }
  if (slot && (slot->width <= 0 || slot->height <= 0)) slot.reset();
  return slot ? &*slot : nullptr;
}

int32_t Textures::texture(const tinygltf::TextureInfo& info, LdrEncoding ldr, const std::string& what) {
  if (info.texCoord != 0) c_.warn(what + ".texCoord = " + std::to_string(info.texCoord) + " not supported; TEXCOORD_0 used");
  if (info.extensions.count("KHR_texture_transform")) c_.warn(what + ".extensions.KHR_texture_transform ignored");
  const auto key = std::make_pair(info.index, ldr);
  if (const auto it = scene_textures_.find(key); it != scene_textures_.end()) return it->second;
  const Image* img = image(info.index, ldr, what);
  int32_t index = -1;
  if (img) {
    ImageTexture t;
    t.name = c_.path + " " + element("textures", size_t(info.index));
    t.width = img->width;
    t.height = img->height;
    // The decoded floats move into the texture and leave the cache (a later mean() decodes again):
    // a 2048^2 image is not held twice while the scene loads.
    t.texels = std::move(images_[key]->pixels);
    images_.erase(key);
    apply_sampler(c_.model, c_.model.textures[size_t(info.index)], &t);
    compact_to_bytes(&t, ldr == LdrEncoding::srgb ? ByteEncoding::srgb : ByteEncoding::linear);  // 8-bit images stay 8-bit
    index = int32_t(scene_->add_texture(std::move(t)));
  }
  scene_textures_[key] = index;
  return index;
}

std::optional<Rgb> Textures::mean(int texture_index, LdrEncoding ldr, const std::string& what) {
  const auto key = std::make_pair(texture_index, ldr);
  if (const auto it = means_.find(key); it != means_.end()) return it->second;
  const Image* img = image(texture_index, ldr, what);
  if (!img) return std::nullopt;
  Rgb sum;
  for (const Rgb& p : img->pixels) sum += p;
  const Rgb m = sum * (1.f / float(img->pixels.size()));
  images_.erase(key);  // only its mean is kept (a texture() of it decodes again)
  return means_[key] = m;
}

}  // namespace pathspace::gltf
