// 8-bit textures kept as 8 bits (scene/image_texture.h): 3 bytes a texel instead of 12, looked up
// through a table of each byte's linear value. io/image_io decodes 8-bit files to floats through the
// same tables, so a byte texture returns the same floats, bit for bit, as the decoded image would.
#include <array>

#include "pathspace/math/srgb.h"
#include "pathspace/scene/image_texture.h"

namespace pathspace {

namespace {

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

}  // namespace pathspace
