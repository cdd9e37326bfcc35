// The host-side owner of one image texture in a Scene: linear RGB texels (or, from an 8-bit file,
// 3 bytes a texel and a table of their 256 linear values, texture_bytes.cpp: a quarter of the
// memory, the same floats at lookup) plus the uv transform and addressing. Loaders fill it
// (io/texture_file.h reads files); Scene::view() exposes it as a TextureView.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "pathspace/scene/texture.h"

namespace pathspace {

enum class ByteEncoding : uint8_t { srgb, linear };

// The linear value of each byte under the encoding (256 entries, static storage; texture_bytes.cpp):
// the one table 8-bit files are decoded with, as floats by io/image_io and at lookup for textures.
const float* texture_byte_values(ByteEncoding encoding);

struct ImageTexture {
  std::string name;  // file or scene name, for messages
  int width = 0, height = 0;
  std::vector<Rgb> texels;     // linear RGB, row 0 at the top; empty when `bytes` holds the image
  std::vector<uint8_t> bytes;  // or: 3 bytes a texel (an 8-bit file), decoded by byte_encoding
  ByteEncoding byte_encoding = ByteEncoding::srgb;
  float uscale = 1.f, vscale = 1.f, udelta = 0.f, vdelta = 0.f;
  bool nearest = false;  // nearest-texel lookup (procedural patterns baked into a few texels, Mitsuba's filter_type nearest)
  TextureWrap wrap = TextureWrap::repeat;

  TextureView view() const {
    const bool compact = !bytes.empty();
    return {texels.data(), width, height, uscale, vscale, udelta, vdelta, nearest, wrap, compact ? bytes.data() : nullptr,
            compact ? texture_byte_values(byte_encoding) : nullptr};
  }
  size_t texel_count() const { return bytes.empty() ? texels.size() : bytes.size() / 3; }
  Rgb texel(size_t i) const {
    if (bytes.empty()) return texels[i];
    const float* v = texture_byte_values(byte_encoding);
    return Rgb(v[bytes[3 * i]], v[bytes[3 * i + 1]], v[bytes[3 * i + 2]]);
  }
  // What the image takes in memory as rendered.
  size_t memory_bytes() const { return bytes.size() + texels.size() * sizeof(Rgb); }
  // Mean texel value (stand-in where a texture cannot be bound, e.g. on an emitter).
  Rgb mean() const {
    Rgb sum;
    const size_t n = texel_count();
    for (size_t i = 0; i < n; ++i) sum += texel(i);
    return n == 0 ? Rgb() : sum * (1.f / float(n));
  }
};

}  // namespace pathspace
