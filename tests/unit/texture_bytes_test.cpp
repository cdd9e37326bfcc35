// 8-bit textures kept as 8 bits (scene/texture_bytes.h): a texture of 8-bit values compacts to
// 3 bytes a texel and looks up the very same floats (bit for bit) at every point; a texture with any
// other value stays float; a PNG read as a scene texture is compacted, a float file is not.
#include <gtest/gtest.h>

#include <cstring>

#include "pathspace/io/image_io.h"
#include "pathspace/io/texture_file.h"
#include "pathspace/math/srgb.h"
#include "pathspace/scene/texture_bytes.h"
#include "support/temp_dir.h"

namespace pathspace {
namespace {

ImageTexture decoded_8bit(ByteEncoding e) {
  ImageTexture t;
  t.width = 5;
  t.height = 3;
  for (int i = 0; i < 15; ++i) {
    const int b[3] = {(i * 37) % 256, (i * 91 + 7) % 256, 255 - (i * 13) % 256};
    Rgb c;
    for (int k = 0; k < 3; ++k) c[k] = e == ByteEncoding::srgb ? linear_from_srgb(float(b[k]) / 255.f) : float(b[k]) / 255.f;
    t.texels.push_back(c);
  }
  return t;
}

bool same_bits(const Rgb& a, const Rgb& b) { return std::memcmp(&a, &b, sizeof(Rgb)) == 0; }

TEST(TextureBytes, CompactedLookupsAreBitIdentical) {
  for (const ByteEncoding e : {ByteEncoding::srgb, ByteEncoding::linear})
    for (const TextureWrap wrap : {TextureWrap::repeat, TextureWrap::mirror, TextureWrap::clamp}) {
      ImageTexture floats = decoded_8bit(e);
      floats.wrap = wrap;
      ImageTexture bytes = floats;
      ASSERT_TRUE(compact_to_bytes(&bytes, e));
      EXPECT_TRUE(bytes.texels.empty());
      EXPECT_EQ(bytes.memory_bytes(), 15u * 3u);
      EXPECT_EQ(bytes.texel_count(), 15u);
      for (size_t i = 0; i < 15; ++i) EXPECT_TRUE(same_bits(bytes.texel(i), floats.texels[i])) << i;
      for (float u = -1.3f; u < 2.f; u += 0.173f)
        for (float v = -0.7f; v < 1.6f; v += 0.131f)
          ASSERT_TRUE(same_bits(texture_lookup(bytes.view(), {u, v}), texture_lookup(floats.view(), {u, v}))) << u << " " << v;
      EXPECT_TRUE(same_bits(bytes.mean(), floats.mean()));
    }
}

TEST(TextureBytes, OtherValuesStayFloat) {
  ImageTexture t = decoded_8bit(ByteEncoding::srgb);
  t.texels[7].g = 0.123456f;  // no byte decodes to it
  EXPECT_FALSE(compact_to_bytes(&t, ByteEncoding::srgb));
  EXPECT_TRUE(t.bytes.empty());
  EXPECT_EQ(t.texels.size(), 15u);
  ImageTexture linear = decoded_8bit(ByteEncoding::linear);
  EXPECT_FALSE(compact_to_bytes(&linear, ByteEncoding::srgb));  // linear values under the sRGB table
}

TEST(TextureBytes, PngTexturesAreKeptAsBytesExrAsFloats) {
  testing::TempDir dir("texture-bytes");
  Image img(3, 2);
  for (int i = 0; i < 6; ++i) img.pixels[size_t(i)] = Rgb(0.1f * float(i), 0.5f, 1.f - 0.15f * float(i));
  write_image(dir.file("t.png"), img);
  write_image(dir.file("t.exr"), img);
  Scene scene;
  TextureFiles files;
  const ImageTexture png = scene.textures[files.add(&scene, dir.file("t.png"), LdrEncoding::srgb)];
  EXPECT_EQ(png.memory_bytes(), 6u * 3u);
  const Image decoded = read_image(dir.file("t.png"), LdrEncoding::srgb);
  for (size_t i = 0; i < 6; ++i) EXPECT_TRUE(same_bits(png.texel(i), decoded.pixels[i])) << i;
  const ImageTexture exr = scene.textures[files.add(&scene, dir.file("t.exr"), LdrEncoding::srgb)];
  EXPECT_EQ(exr.memory_bytes(), 6u * sizeof(Rgb));
}

}  // namespace
}  // namespace pathspace
