// 8-bit textures kept as 8 bits (scene/image_texture.h): a byte texture looks up the very same
// floats (bit for bit) as the float texture of its decoded values, at every point and in every
// addressing mode; files read as scene textures are bytes when 8-bit (PNG) and floats otherwise
// (EXR), and their bytes decode to exactly what the float reader gives.
#include <gtest/gtest.h>

#include <cstring>

#include "pathspace/io/image_io.h"
#include "pathspace/io/texture_file.h"
#include "support/temp_dir.h"

namespace pathspace {
namespace {

bool same_bits(const Rgb& a, const Rgb& b) { return std::memcmp(&a, &b, sizeof(Rgb)) == 0; }

TEST(TextureBytes, LookupsAreTheFloatTexturesBitForBit) {
  for (const ByteEncoding e : {ByteEncoding::srgb, ByteEncoding::linear})
    for (const TextureWrap wrap : {TextureWrap::repeat, TextureWrap::mirror, TextureWrap::clamp})
      for (const bool nearest : {false, true}) {
        ImageTexture bytes, floats;
        for (ImageTexture* t : {&bytes, &floats}) t->width = 5, t->height = 3, t->wrap = wrap, t->nearest = nearest;
        bytes.byte_encoding = e;
        const float* value = texture_byte_values(e);
        for (int i = 0; i < 15; ++i) {
          const uint8_t b[3] = {uint8_t((i * 37) % 256), uint8_t((i * 91 + 7) % 256), uint8_t(255 - (i * 13) % 256)};
          bytes.bytes.insert(bytes.bytes.end(), b, b + 3);
          floats.texels.push_back(Rgb(value[b[0]], value[b[1]], value[b[2]]));
        }
        EXPECT_EQ(bytes.memory_bytes(), 15u * 3u);
        EXPECT_EQ(bytes.texel_count(), 15u);
        for (size_t i = 0; i < 15; ++i) EXPECT_TRUE(same_bits(bytes.texel(i), floats.texels[i])) << i;
        for (float u = -1.3f; u < 2.f; u += 0.173f)
          for (float v = -0.7f; v < 1.6f; v += 0.131f)
            ASSERT_TRUE(same_bits(texture_lookup(bytes.view(), {u, v}), texture_lookup(floats.view(), {u, v}))) << u << " " << v;
        EXPECT_TRUE(same_bits(bytes.mean(), floats.mean()));
      }
}

TEST(TextureBytes, PngTexturesAreKeptAsBytesExrAsFloats) {
  testing::TempDir dir("texture-bytes");
  Image img(3, 2);
  for (int i = 0; i < 6; ++i) img.pixels[size_t(i)] = Rgb(0.1f * float(i), 0.5f, 1.f - 0.15f * float(i));
  write_image(dir.file("t.png"), img);
  write_image(dir.file("t.exr"), img);
  Scene scene;
  TextureFiles files;
  for (const LdrEncoding ldr : {LdrEncoding::srgb, LdrEncoding::linear}) {
    const ImageTexture png = scene.textures[files.add(&scene, dir.file("t.png"), ldr)];
    EXPECT_EQ(png.memory_bytes(), 6u * 3u);
    const Image decoded = read_image(dir.file("t.png"), ldr);
    for (size_t i = 0; i < 6; ++i) EXPECT_TRUE(same_bits(png.texel(i), decoded.pixels[i])) << i;
  }
  const ImageTexture exr = scene.textures[files.add(&scene, dir.file("t.exr"), LdrEncoding::srgb)];
  EXPECT_EQ(exr.memory_bytes(), 6u * sizeof(Rgb));
  EXPECT_FALSE(read_image_bytes(dir.file("t.exr")).has_value());
}

}  // namespace
}  // namespace pathspace
