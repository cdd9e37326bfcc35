// Image files as scene textures: read through image_io (EXR, PFM, PNG, JPG, TGA, HDR, BMP) into a
// Scene's texture store. A file shared by several materials with the same encoding, uv transform
// and addressing is read and stored once; an 8-bit file's colours are kept as 8 bits
// (scene/image_texture.h). Read errors are image_io's pathspace::Error naming the file.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <tuple>
#include <utility>

#include "pathspace/io/image_io.h"
#include "pathspace/scene/scene.h"

namespace pathspace {

struct TextureUvTransform {
  float uscale = 1.f, vscale = 1.f, udelta = 0.f, vdelta = 0.f;
};

// How a texture is read between and beyond its texels (scene/texture.h).
struct TextureSampling {
  TextureWrap wrap = TextureWrap::repeat;
  bool nearest = false;
};

// An image's texels into a texture: an 8-bit one as its bytes, decoded at lookup by `ldr`'s table
// (scene/image_texture.h), any other as float texels.
inline void take_texels(ImageTexture* t, ByteImage&& bytes, LdrEncoding ldr) {
  t->width = bytes.width;
  t->height = bytes.height;
  t->bytes = std::move(bytes.rgb);
  t->byte_encoding = byte_encoding(ldr);
}
inline void take_texels(ImageTexture* t, Image&& image) {
  t->width = image.width;
  t->height = image.height;
  t->texels = std::move(image.pixels);
}

class TextureFiles {
 public:
  // Index of the texture in scene->textures (read on first use). ImageContent::scalar: a float
  // texture such as cutout opacity (image_io.h).
  uint32_t add(Scene* scene, const std::string& path, LdrEncoding ldr, const TextureUvTransform& uv = {},
               ImageContent content = ImageContent::color, const TextureSampling& sampling = {}) {
    const Key key{path, int(ldr), int(content), uv.uscale, uv.vscale, uv.udelta, uv.vdelta, int(sampling.wrap), sampling.nearest};
    const auto it = loaded_.find(key);
    if (it != loaded_.end()) return it->second;
    ImageTexture t;
    t.name = path;
    // An 8-bit colour file stays 8-bit (scene/image_texture.h), read without a float image.
    std::optional<ByteImage> bytes = content == ImageContent::color ? read_image_bytes(path) : std::nullopt;
    if (bytes) take_texels(&t, std::move(*bytes), ldr);
    else take_texels(&t, read_image(path, ldr, content));
    t.uscale = uv.uscale;
    t.vscale = uv.vscale;
    t.udelta = uv.udelta;
    t.vdelta = uv.vdelta;
    t.wrap = sampling.wrap;
    t.nearest = sampling.nearest;
    const uint32_t index = scene->add_texture(std::move(t));
    loaded_.emplace(key, index);
    return index;
  }

 private:
  using Key = std::tuple<std::string, int, int, float, float, float, float, int, bool>;
  std::map<Key, uint32_t> loaded_;
};

}  // namespace pathspace
