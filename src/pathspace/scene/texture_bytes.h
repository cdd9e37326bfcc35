// 8-bit textures kept as 8 bits (3 bytes a texel instead of 12): a texture read from an 8-bit file
// holds only the 256 values its decoding gives each byte (sRGB-decoded or byte / 255), so it is
// stored as those bytes and a 256-entry table of their linear values, and looked up through the
// table (scene/texture.h texture_texel). The tables are built exactly as io/image_io decodes, so a
// compacted texture returns the same floats, bit for bit, as the decoded one did.
#pragma once

#include <cstdint>

#include "pathspace/scene/image_texture.h"

namespace pathspace {

// Replaces t's float texels by bytes when every channel of every texel is one of the encoding's 256
// values (true); leaves a texture with any other value (a 16-bit or float file) as it is (false).
bool compact_to_bytes(ImageTexture* t, ByteEncoding encoding);

}  // namespace pathspace
