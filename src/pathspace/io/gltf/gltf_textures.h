// glTF textures → scene image textures. Images are decoded by io/image_io (embedded ones from the
// bytes tinygltf kept, external ones from their file relative to the glTF file), sRGB or linear as
// the material slot needs; each (image, encoding) pair is decoded once. An image that cannot be read
// is a warning and the slot keeps its constant factor. glTF's uv origin is the image's top-left
// corner: the mesh loader stores v' = 1 - v so that our bottom-row v = 0 convention holds.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <utility>

#include "pathspace/film/image.h"
#include "pathspace/io/gltf/gltf_context.h"
#include "pathspace/io/image_io.h"
#include "pathspace/scene/scene.h"

namespace pathspace::gltf {

class Textures {
 public:
  Textures(const Context& c, Scene* scene) : c_(c), scene_(scene) {}

  // The scene texture of a material's textureInfo (`what` names it, e.g. "materials[2].pbrMetallicRoughness
  // .baseColorTexture"), or -1 with a warning when its image cannot be read.
  int32_t texture(const tinygltf::TextureInfo& info, LdrEncoding ldr, const std::string& what);
  // Its mean texel value, for slots our materials cannot texture; nullopt (warning) when unreadable.
  std::optional<Rgb> mean(int texture_index, LdrEncoding ldr, const std::string& what);

 private:
  // A texture's image as stored: `name` for errors, `element` ("images[2]") for warnings.
  struct Encoded {
    std::string name, element, bytes;
  };
  // The encoded image of texture `texture_index`, or nullopt with a warning.
  std::optional<Encoded> encoded(int texture_index);
  // Its float decoding, or nullopt with a warning.
  std::optional<Image> decoded(const Encoded& e, LdrEncoding ldr);
  // Its bytes when it is an 8-bit image (*out nullopt for another kind); false with a warning when
  // it cannot be decoded.
  bool decoded_bytes(const Encoded& e, std::optional<ByteImage>* out);

  const Context& c_;
  Scene* scene_;
  // Images are decoded when bound or averaged, one at a time, and not kept: an 8-bit one goes to
  // its texture's bytes (or its mean) without a float image in between.
  std::map<std::pair<int, LdrEncoding>, std::optional<Rgb>> means_;  // nullopt: unreadable (warned once)
  std::map<std::pair<int, LdrEncoding>, int32_t> scene_textures_;
};

}  // namespace pathspace::gltf
