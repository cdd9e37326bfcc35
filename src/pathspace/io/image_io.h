// Image files: EXR (OpenEXR, linear float RGB), PFM (linear float, standard bottom-row-first order)
// and PNG (sRGB-encoded 8 bit, clamped). The format follows the file extension. Writes go to a
// temporary file in the same folder that is renamed into place, so a failure never leaves a
// half-written image. Errors are pathspace::Error naming the file.
#pragma once

#include <cstdint>
#include <string>
#include <vector>
#include <optional>

#include "pathspace/film/image.h"
#include "pathspace/scene/image_texture.h"  // ByteEncoding, texture_byte_values

namespace pathspace {

enum class ImageFormat { exr, pfm, png };

// Format from the extension (case-insensitive); throws pathspace::Error for anything else.
ImageFormat image_format_from_path(const std::string& path);

void write_image(const std::string& path, const Image& image);
// How much time encoding may take: `compact` (what write_image writes) or `fast` for files that are
// soon replaced (`render --write-every`): EXR without compression (ZIP gains little on noisy float
// images and costs ~90 ms per 512x512 image), PNG at zlib's fastest level. The pixels are the same
// either way.
enum class ImageEncoding { compact, fast };

// The bytes write_image would write (for OutputSet, io/atomic_file.h).
std::string encode_image(const std::string& path, const Image& image, ImageEncoding encoding = ImageEncoding::compact);
// How 8- and 16-bit files are turned into linear floats: sRGB-decoded (colour images), or v / max
// (textures that hold linear data, e.g. pbrt's encoding "linear"). Float formats are always linear.
enum class LdrEncoding { srgb, linear };

// The most pixels an image read may have (2^27: 16384 x 8192, 1.5 GiB as float RGB). Checked from
// the header before anything is allocated, so a small file (a compressed EXR or PNG) cannot ask for
// gigabytes.
inline constexpr uint64_t kMaxImagePixels = uint64_t(1) << 27;
// Lowers (or restores) that limit for this process: the image fuzzer reads at most 2^22 pixels, so
// each input stays fast while every code path stays reachable.
void set_max_image_pixels(uint64_t pixels);

// What a read returns of a file: its colour, or a scalar in all three channels as pbrt-v4 reads a
// float texture (used for cutout opacity): the alpha channel where the file has one that is not 1
// everywhere (alpha is linear, never sRGB-decoded), else the mean of the colour channels.
enum class ImageContent { color, scalar };

// Reads EXR, PFM, PNG (and what stb reads: JPG, HDR, TGA, BMP).
Image read_image(const std::string& path, LdrEncoding ldr = LdrEncoding::srgb, ImageContent content = ImageContent::color);
// The same for bytes already in memory (images embedded in glTF files); `path` names them in
// errors, and its extension (if any) picks the decoder where the content does not.
Image decode_image(const std::string& path, const std::string& bytes, LdrEncoding ldr = LdrEncoding::srgb,
                   ImageContent content = ImageContent::color);

// An 8-bit file's colour channels as stored, 3 bytes a pixel (grey replicated, alpha dropped): the
// bytes read_image's colour decoding looks up in its table, for textures kept as 8 bits
// (scene/image_texture.h) without a float image in between. nullopt for a file that is not 8-bit
// (EXR, PFM, HDR, 16-bit PNG); the same checks and errors as decode_image otherwise.
struct ByteImage {
  int width = 0, height = 0;
  std::vector<uint8_t> rgb;
};
std::optional<ByteImage> read_image_bytes(const std::string& path);
// The table a ByteImage's bytes are decoded with (scene/image_texture.h's, one table for both).
inline ByteEncoding byte_encoding(LdrEncoding ldr) { return ldr == LdrEncoding::srgb ? ByteEncoding::srgb : ByteEncoding::linear; }
inline const float* byte_values(LdrEncoding ldr) { return texture_byte_values(byte_encoding(ldr)); }
std::optional<ByteImage> decode_image_bytes(const std::string& path, const std::string& bytes);

}  // namespace pathspace
