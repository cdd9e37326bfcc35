#include "pathspace/scene/texture_bytes.h"

#include <algorithm>
#include <array>

#include "pathspace/math/srgb.h"

namespace pathspace {

namespace {

// The same expressions as io/image_io's 8-bit decoding (decode_stb): equal floats, not close ones.
std::array<float, 256> table(ByteEncoding encoding) {
  std::array<float, 256> t{};
  for (int i = 0; i < 256; ++i) t[size_t(i)] = encoding == ByteEncoding::srgb ? linear_from_srgb(float(i) / 255.f) : float(i) / 255.f;
  return t;
}

}  // namespace

const float* texture_byte_values(ByteEncoding encoding) {
  static const std::array<float, 256> srgb = table(ByteEncoding::srgb), linear = table(ByteEncoding::linear);
  return encoding == ByteEncoding::srgb ? srgb.data() : linear.data();
}

bool compact_to_bytes(ImageTexture* t, ByteEncoding encoding) {
  if (t->texels.empty() || !t->bytes.empty()) return false;
  const float* values = texture_byte_values(encoding);
  std::vector<uint8_t> bytes(t->texels.size() * 3);
  for (size_t i = 0; i < t->texels.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      const float v = t->texels[i][c];
      const float* at = std::lower_bound(values, values + 256, v);  // the table increases strictly
      if (at == values + 256 || *at != v) return false;
      bytes[3 * i + size_t(c)] = uint8_t(at - values);
    }
  t->bytes = std::move(bytes);
  t->byte_encoding = encoding;
  t->texels.clear();
  t->texels.shrink_to_fit();
  return true;
}

}  // namespace pathspace
