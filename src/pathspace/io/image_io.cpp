// Image files. Every format is encoded into memory first (encode_image) and then written through
// write_file_atomically or an OutputSet (io/atomic_file.h), so all formats share one failure handling.
// Non-finite pixels: EXR and PFM store them unchanged; PNG stores NaN as 0 and clamps ±Inf
// (film/tonemap.h, to_srgb8).
#include "pathspace/io/image_io.h"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <bit>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <climits>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
#include <mutex>
#include <string_view>
#include <thread>

#include <OpenEXR/IexBaseExc.h>
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfIO.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStdIO.h>
#include <OpenEXR/ImfThreading.h>

// stb is compiled here, with static linkage so another library bundling stb (tinygltf) cannot
// clash with it. Its own warnings are not ours.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wall"
#pragma GCC diagnostic ignored "-Wextra"
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_WRITE_STATIC
#define STB_IMAGE_WRITE_IMPLEMENTATION
// PNG's deflate through zlib (stb's own hook): 2-3x faster than stb's compressor at the same size,
// which matters for --write-every (docs/results/io-and-overheads.md, "Checkpoints and periodic outputs").
#define STBIW_ZLIB_COMPRESS pathspace_png_deflate
// Debian's stb_image.h calls memcpy with a null source and length 0 on some damaged PNGs: undefined
// but harmless, and third-party. Sanitizer and fuzz builds compile this file without UBSan's
// nonnull check (src/pathspace/CMakeLists.txt; docs/fuzzing.md).
// stb reads only the formats docs/cli.md lists (PNG, JPG, TGA, HDR, BMP): its PNM reader overflows
// an int on a long header number (undefined; found by fuzz_image, tests/fuzz/corpus/image/
// crash_pnm_header_int_overflow), and PSD, PIC and GIF are formats no scene of ours uses.
// A truncated uncompressed TGA leaves the rows stb could not read unwritten (stbi__getn's result is
// not checked there), so the image held whatever the allocator returned: a different image at each
// read (found by fuzz_image's byte-versus-float check, tests/fuzz/corpus/image/crash_tga_truncated_rows).
// Zeroed allocations make such rows black, as stb's RLE reader already reads bytes past the end.
#define STBI_MALLOC(size) calloc(1, size)
#define STBI_REALLOC(p, size) realloc(p, size)
#define STBI_FREE(p) free(p)
#define STBI_NO_PNM
#define STBI_NO_PSD
#define STBI_NO_PIC
#define STBI_NO_GIF
#include <stb_image.h>
#include <zlib.h>
// The zlib level of the PNG being encoded on this thread (ImageEncoding: fast = Z_BEST_SPEED).
static thread_local int pathspace_png_level = Z_DEFAULT_COMPRESSION;
// stb frees the result with STBIW_FREE (free).
static unsigned char* pathspace_png_deflate(unsigned char* data, int data_len, int* out_len, int /*quality*/) {
  uLongf size = compressBound(uLong(data_len));
  auto* out = static_cast<unsigned char*>(malloc(size));
  if (!out || compress2(out, &size, data, uLong(data_len), pathspace_png_level) != Z_OK) {
    free(out);
    return nullptr;
  }
  *out_len = int(size);
  return out;
}
#include <stb_image_write.h>
#pragma GCC diagnostic pop

#include "pathspace/base/error.h"
#include "pathspace/film/tonemap.h"
#include "pathspace/io/atomic_file.h"
#include "pathspace/io/file_bytes.h"
#include "pathspace/parallel/parallel_for.h"

namespace pathspace {
namespace {

namespace fs = std::filesystem;

static_assert(sizeof(Rgb) == 3 * sizeof(float), "EXR slices and PFM rows assume packed Rgb");

[[noreturn]] void fail(const std::string& path, const std::string& why) { throw Error(path + ": " + why); }

std::atomic<uint64_t>& max_image_pixels() {
  static std::atomic<uint64_t> limit{kMaxImagePixels};
  return limit;
}

void check_pixel_count(const std::string& path, uint64_t w, uint64_t h) {
  const uint64_t limit = max_image_pixels().load();
  if (w * h > limit) fail(path, fmt::format("{}x{} pixels: more than the {} an image may have (io/image_io.h)", w, h, limit));
}

std::string lower_extension(const std::string& path) {
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return ext;
}

// ---- writing ---------------------------------------------------------------------------------


// OpenEXR's thread pool, made once with a thread per core; each file uses as many of them as the
// render may (ThreadLimit::active()).
void start_exr_threads() {
  static std::once_flag once;
  std::call_once(once, [] { Imf::setGlobalThreadCount(int(std::max(1u, std::thread::hardware_concurrency()))); });
}

std::string encode_exr(const Image& image, ImageEncoding encoding) {
  Imf::Header header(image.width, image.height);
  header.compression() = encoding == ImageEncoding::fast ? Imf::NO_COMPRESSION : Imf::ZIP_COMPRESSION;
  Imf::FrameBuffer frame;
  // OpenEXR's Slice takes a non-const pointer but only reads through it when writing.
  char* base = reinterpret_cast<char*>(const_cast<Rgb*>(image.pixels.data()));
  const char* names[3] = {"R", "G", "B"};
  for (int c = 0; c < 3; ++c) {
    header.channels().insert(names[c], Imf::Channel(Imf::FLOAT));
    frame.insert(names[c], Imf::Slice(Imf::FLOAT, base + c * sizeof(float), sizeof(Rgb),
                                      sizeof(Rgb) * size_t(image.width)));
  }
  Imf::StdOSStream out;
  {
    // Line blocks are compressed in parallel (the file's bytes do not depend on how many threads).
    start_exr_threads();
    Imf::OutputFile file(out, header, ThreadLimit::active());  // the destructor writes the line offset table
    file.setFrameBuffer(frame);
    file.writePixels(image.height);
  }
  return out.str();
}

void put_f32_le(char* dst, float v) {
  const uint32_t bits = std::bit_cast<uint32_t>(v);
  for (int i = 0; i < 4; ++i) dst[i] = char((bits >> (8 * i)) & 0xffu);
}

float get_f32(const char* src, bool little_endian) {
  uint32_t bits = 0;
  for (int i = 0; i < 4; ++i) {
    const uint32_t byte = static_cast<unsigned char>(src[little_endian ? i : 3 - i]);
    bits |= byte << (8 * i);
  }
  return std::bit_cast<float>(bits);
}

// PFM: "PF\n<w> <h>\n-1.0\n" (negative scale = little endian), then rows from the bottom up.
std::string encode_pfm(const Image& image) {
  std::string out = fmt::format("PF\n{} {}\n-1.0\n", image.width, image.height);
  const size_t header = out.size(), row_bytes = size_t(image.width) * 12;
  out.resize(header + row_bytes * size_t(image.height));
  for (int y = 0; y < image.height; ++y) {
    char* dst = out.data() + header + row_bytes * size_t(image.height - 1 - y);
    for (int x = 0; x < image.width; ++x)
      for (int c = 0; c < 3; ++c) put_f32_le(dst + 12 * size_t(x) + 4 * size_t(c), image.at(x, y)[c]);
  }
  return out;
}

std::string encode_png(const std::string& path, const Image& image, ImageEncoding encoding) {
  pathspace_png_level = encoding == ImageEncoding::fast ? Z_BEST_SPEED : Z_DEFAULT_COMPRESSION;
  std::vector<unsigned char> px(image.size() * 3);
  parallel_for(image.size(), size_t(1) << 14, [&](size_t begin, size_t end) {
    for (size_t i = begin; i < end; ++i)
      for (int c = 0; c < 3; ++c) px[3 * i + size_t(c)] = to_srgb8(image.pixels[i][c]);
  });
  std::string out;
  auto sink = [](void* ctx, void* data, int size) {
    static_cast<std::string*>(ctx)->append(static_cast<const char*>(data), size_t(size));
  };
  if (image.width > INT_MAX / 3 || !stbi_write_png_to_func(sink, &out, image.width, image.height, 3, px.data(),
                                                           image.width * 3))
    fail(path, "PNG encoding failed");
  return out;
}

// ---- reading ---------------------------------------------------------------------------------

// OpenEXR input from bytes already in memory, named after the file for OpenEXR's messages.
class MemoryIStream : public Imf::IStream {
 public:
  MemoryIStream(const std::string& name, const std::string& bytes) : Imf::IStream(name.c_str()), bytes_(bytes) {}
  bool read(char c[], int n) override {
    if (n < 0 || pos_ > bytes_.size() || size_t(n) > bytes_.size() - pos_)
      throw Iex::InputExc("early end of file (truncated data)");
    std::memcpy(c, bytes_.data() + pos_, size_t(n));
    pos_ += size_t(n);
    return pos_ < bytes_.size();
  }
  uint64_t tellg() override { return pos_; }
  void seekg(uint64_t pos) override { pos_ = size_t(pos); }

 private:
  const std::string& bytes_;
  size_t pos_ = 0;
};

// ImageContent::scalar: the alpha channel in all three channels where it is not 1 everywhere, else
// the mean of the colour channels.
Image scalar_image(Image color, const std::vector<float>& alpha) {
  const bool use_alpha = std::any_of(alpha.begin(), alpha.end(), [](float a) { return a != 1.f; });
  for (size_t i = 0; i < color.size(); ++i) {
    const Rgb& c = color.pixels[i];
    color.pixels[i] = Rgb(use_alpha ? alpha[i] : (c.r + c.g + c.b) * (1.f / 3.f));
  }
  return color;
}

Image decode_exr(const std::string& path, const std::string& bytes, ImageContent content) {
  try {
    MemoryIStream in(path, bytes);
    Imf::InputFile file(in);
    const Imath::Box2i dw = file.header().dataWindow();
    const int64_t w = int64_t(dw.max.x) - dw.min.x + 1, h = int64_t(dw.max.y) - dw.min.y + 1;
    if (w <= 0 || h <= 0 || w > INT_MAX || h > INT_MAX) fail(path, "bad EXR data window");
    check_pixel_count(path, uint64_t(w), uint64_t(h));
    const Imf::ChannelList& channels = file.header().channels();
    const bool rgb = channels.findChannel("R") || channels.findChannel("G") || channels.findChannel("B");
    if (!rgb && !channels.findChannel("Y")) fail(path, "EXR has no R, G, B or Y channel");
    Image image(static_cast<int>(w), static_cast<int>(h));
    char* base = reinterpret_cast<char*>(image.pixels.data());
    Imf::FrameBuffer frame;
    const char* names[3] = {"R", "G", "B"};
    for (int c = 0; c < (rgb ? 3 : 1); ++c)  // missing channels are filled with 0
      frame.insert(rgb ? names[c] : "Y", Imf::Slice::Make(Imf::FLOAT, base + c * sizeof(float), dw, sizeof(Rgb),
                                                          sizeof(Rgb) * size_t(w)));
    std::vector<float> alpha;
    if (content == ImageContent::scalar && channels.findChannel("A")) {
      alpha.resize(image.size());
      frame.insert("A", Imf::Slice::Make(Imf::FLOAT, alpha.data(), dw, sizeof(float), sizeof(float) * size_t(w)));
    }
    file.setFrameBuffer(frame);
    file.readPixels(dw.min.y, dw.max.y);
    if (!rgb)
      for (Rgb& p : image.pixels) p.g = p.b = p.r;
    return content == ImageContent::scalar ? scalar_image(std::move(image), alpha) : image;
  } catch (const Error&) {
    throw;
  } catch (const std::exception& e) {  // OpenEXR's Iex exceptions and bad_alloc
    fail(path, std::string("bad EXR file: ") + e.what());
  }
}

// PFM: "PF" (RGB) or "Pf" (grey), whitespace, width, height, scale (its sign gives the byte order:
// negative = little endian; its magnitude scales the values), one whitespace byte, then float rows
// from the bottom of the image to the top.
Image decode_pfm(const std::string& path, const std::string& b) {
  auto bad = [&](const std::string& why) { fail(path, "bad PFM header: " + why); };
  if (b.size() < 3 || b[0] != 'P' || (b[1] != 'F' && b[1] != 'f')) bad("expected 'PF' or 'Pf'");
  const int channels = b[1] == 'F' ? 3 : 1;
  size_t pos = 2;
  auto is_space = [](char c) { return c == ' ' || c == '\n' || c == '\r' || c == '\t'; };
  auto token = [&](const char* what) {
    if (pos >= b.size() || !is_space(b[pos])) bad(std::string("expected whitespace before ") + what);
    while (pos < b.size() && is_space(b[pos])) ++pos;
    const size_t start = pos;
    while (pos < b.size() && !is_space(b[pos])) ++pos;
    if (start == pos) bad(std::string("missing ") + what);
    return std::string_view(b).substr(start, pos - start);
  };
  auto parse_size = [&](const char* what) {
    const std::string_view t = token(what);
    int v = 0;
    const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
    if (ec != std::errc() || end != t.data() + t.size() || v <= 0 || v > (1 << 24))
      bad(fmt::format("bad {} '{}'", what, t));
    return v;
  };
  const int w = parse_size("width"), h = parse_size("height");
  check_pixel_count(path, uint64_t(w), uint64_t(h));
  const std::string_view st = token("scale");
  double scale = 0;
  const auto [end, ec] = std::from_chars(st.data(), st.data() + st.size(), scale);
  if (ec != std::errc() || end != st.data() + st.size() || scale == 0 || !std::isfinite(scale))
    bad(fmt::format("bad scale '{}'", st));
  if (pos >= b.size() || !is_space(b[pos])) bad("expected a newline after the scale");
  ++pos;  // exactly one whitespace byte separates header and data

  const size_t row_bytes = size_t(w) * size_t(channels) * 4, expected = row_bytes * size_t(h);
  if (b.size() - pos < expected)
    fail(path, fmt::format("truncated data: expected {} bytes of pixels, found {}", expected, b.size() - pos));
  const bool little = scale < 0;
  const float factor = float(std::abs(scale));
  Image image(w, h);
  for (int row = 0; row < h; ++row) {
    const char* src = b.data() + pos + row_bytes * size_t(row);
    for (int x = 0; x < w; ++x) {
      Rgb& p = image.at(x, h - 1 - row);  // file row 0 is the bottom one
      for (int c = 0; c < 3; ++c) {
        const float v = get_f32(src + 4 * size_t(x * channels + (channels == 3 ? c : 0)), little);
        p[c] = factor == 1.f ? v : v * factor;  // the usual |scale| 1: bit exact, NaN payloads kept
      }
    }
  }
  return image;
}

// 1-4 channels (grey, grey+alpha, RGB, RGBA) of type T, colour converted by to_linear; alpha (v /
// max: to_unit) is read for ImageContent::scalar only.
template <class T, class F, class U>
Image image_from_channels(const T* px, int w, int h, int n, F to_linear, U to_unit, ImageContent content) {
  Image image(w, h);
  std::vector<float> alpha;
  const bool has_alpha = n == 2 || n == 4;
  if (content == ImageContent::scalar && has_alpha) alpha.resize(image.size());
  for (size_t i = 0; i < image.size(); ++i) {
    const T* p = px + i * size_t(n);
    image.pixels[i] = n >= 3 ? Rgb(to_linear(p[0]), to_linear(p[1]), to_linear(p[2])) : Rgb(to_linear(p[0]));
    if (!alpha.empty()) alpha[i] = to_unit(p[n - 1]);
  }
  return content == ImageContent::scalar ? scalar_image(std::move(image), alpha) : image;
}

// stb_image grows its buffer to each IDAT chunk's declared length before it reads the chunk, so a
// PNG of a few hundred bytes that declares a 1.4 GB chunk allocates 2 GB (found by the image
// fuzzer). Every chunk of a real PNG lies inside the file, so one that does not is an error first.
void check_png_chunk_lengths(const std::string& path, const std::string& bytes) {
  static constexpr char kSignature[8] = {'\x89', 'P', 'N', 'G', '\r', '\n', '\x1a', '\n'};
  if (bytes.size() < 8 || std::memcmp(bytes.data(), kSignature, 8) != 0) return;
  size_t at = 8;
  while (bytes.size() - at >= 8) {
    const auto* b = reinterpret_cast<const unsigned char*>(bytes.data() + at);
    const uint64_t length = uint64_t(b[0]) << 24 | uint64_t(b[1]) << 16 | uint64_t(b[2]) << 8 | uint64_t(b[3]);
    if (length + 12 > bytes.size() - at)
      fail(path, fmt::format("PNG chunk at byte {} declares {} bytes, more than the file holds", at, length));
    if (std::memcmp(b + 4, "IEND", 4) == 0) return;
    at += size_t(length) + 12;
  }
}

// stb_image's JPEG reader fills a table of at most 256 Huffman codes from a DHT segment's 16 code
// counts without checking that they sum to 256 or less, and writes past the table when they do not
// (found by the image fuzzer, UBSan). Such a table is corrupt for any reader: an error first. The
// walk follows the markers, skips entropy-coded data (stuffed 0xFF00 and restart markers) and reads
// bytes past the end of the file as 0, as stb does.
void check_jpeg_huffman_tables(const std::string& path, const std::string& bytes) {
  const auto* b = reinterpret_cast<const unsigned char*>(bytes.data());
  const size_t n = bytes.size();
  size_t at = 0;
  while (at < n && b[at] == 0xFF) ++at;  // stb reads fill bytes before the start-of-image marker too
  if (at == 0 || at >= n || b[at] != 0xD8) return;
  ++at;
  while (at < n) {
    if (b[at] != 0xFF) {
      ++at;
      continue;
    }
    while (at < n && b[at] == 0xFF) ++at;  // fill bytes
    if (at >= n) return;
    const unsigned char marker = b[at++];
    if (marker == 0x00 || marker == 0x01 || (marker >= 0xD0 && marker <= 0xD7)) continue;  // no length field
    if (marker == 0xD9 || at + 2 > n) return;                                           // end of image
    const size_t length = size_t(b[at]) << 8 | size_t(b[at + 1]);
    const size_t end = std::min(n, at + std::max<size_t>(length, 2));
    if (marker == 0xC4) {
      for (size_t p = at + 2; p < end;) {
        size_t codes = 0;
        for (size_t i = p + 1; i < p + 17; ++i) codes += i < n ? b[i] : 0;
        if (codes > 256) fail(path, fmt::format("JPEG Huffman table at byte {} declares {} codes (at most 256)", p, codes));
        p += 17 + codes;
      }
    }
    at = end;
  }
}

// stb's input after the checks every stb decode starts with: size, PNG chunk lengths, JPEG Huffman
// tables and the pixel count its header declares.
struct StbInput {
  const stbi_uc* data;
  int len;
};
StbInput checked_stb_input(const std::string& path, const std::string& bytes) {
  if (bytes.size() > size_t(INT_MAX)) fail(path, "file too large");
  const StbInput in{reinterpret_cast<const stbi_uc*>(bytes.data()), int(bytes.size())};
  check_png_chunk_lengths(path, bytes);
  check_jpeg_huffman_tables(path, bytes);
  int w = 0, h = 0, n = 0;
  if (stbi_info_from_memory(in.data, in.len, &w, &h, &n) && w > 0 && h > 0) check_pixel_count(path, uint64_t(w), uint64_t(h));
  return in;
}

template <typename T>
using StbBuffer = std::unique_ptr<T, void (*)(void*)>;

void check_decoded(const std::string& path, const void* px) {
  if (!px) fail(path, std::string("cannot decode image: ") + stbi_failure_reason());
}

// An 8-bit file's pixels as stored: n channels each.
StbBuffer<stbi_uc> load_8bit(const std::string& path, const StbInput& in, int* w, int* h, int* n) {
  StbBuffer<stbi_uc> px(stbi_load_from_memory(in.data, in.len, w, h, n, 0), stbi_image_free);
  check_decoded(path, px.get());
  return px;
}

// Everything stb reads. HDR (Radiance) is linear already; 8- and 16-bit formats are sRGB-decoded
// unless the caller says they hold linear data (v / max); 8-bit values through the same table as
// 8-bit textures kept as bytes (scene/image_texture.h).
// (stbi_loadf is not used for LDR files because it applies a plain 2.2 gamma, not sRGB.)
Image decode_stb(const std::string& path, const std::string& bytes, LdrEncoding ldr, ImageContent content) {
  const StbInput in = checked_stb_input(path, bytes);
  int w = 0, h = 0, n = 0;
  if (stbi_is_hdr_from_memory(in.data, in.len)) {
    StbBuffer<float> px(stbi_loadf_from_memory(in.data, in.len, &w, &h, &n, 0), stbi_image_free);
    check_decoded(path, px.get());
    const auto same = [](float v) { return v; };
    return image_from_channels(px.get(), w, h, n, same, same, content);
  }
  if (stbi_is_16_bit_from_memory(in.data, in.len)) {
    StbBuffer<stbi_us> px(stbi_load_16_from_memory(in.data, in.len, &w, &h, &n, 0), stbi_image_free);
    check_decoded(path, px.get());
    const bool srgb = ldr == LdrEncoding::srgb;
    return image_from_channels(
        px.get(), w, h, n, [&](stbi_us v) { return srgb ? linear_from_srgb(v / 65535.f) : v / 65535.f; },
        [](stbi_us v) { return v / 65535.f; }, content);
  }
  const StbBuffer<stbi_uc> px = load_8bit(path, in, &w, &h, &n);
  const float* value = byte_values(ldr);
  return image_from_channels(px.get(), w, h, n, [&](stbi_uc v) { return value[v]; }, [](stbi_uc v) { return v / 255.f; }, content);
}

enum class Decoder { exr, pfm, stb };

// The content decides where it can; the extension picks the decoder whose error message fits.
Decoder decoder_for(const std::string& path, const std::string& bytes) {
  const std::string ext = lower_extension(path);
  const bool exr_magic = bytes.size() >= 4 && bytes.compare(0, 4, "\x76\x2f\x31\x01") == 0;
  const bool pfm_magic = bytes.size() >= 2 && bytes[0] == 'P' && (bytes[1] == 'F' || bytes[1] == 'f');
  if (exr_magic || (ext == ".exr" && !pfm_magic)) return Decoder::exr;
  return pfm_magic || ext == ".pfm" ? Decoder::pfm : Decoder::stb;
}

void check_not_empty(const std::string& path, int w, int h) {
  if (w <= 0 || h <= 0) fail(path, fmt::format("{}x{} pixels: the image is empty", w, h));
}

}  // namespace

ImageFormat image_format_from_path(const std::string& path) {
  const std::string ext = lower_extension(path);
  if (ext == ".exr") return ImageFormat::exr;
  if (ext == ".pfm") return ImageFormat::pfm;
  if (ext == ".png") return ImageFormat::png;
  fail(path, "unsupported image extension '" + ext + "' (supported: .exr, .pfm, .png)");
}

std::string encode_image(const std::string& path, const Image& image, ImageEncoding encoding) {
  const ImageFormat format = image_format_from_path(path);
  if (image.width <= 0 || image.height <= 0)
    fail(path, fmt::format("cannot write an empty image ({}x{})", image.width, image.height));
  if (image.pixels.size() != size_t(image.width) * size_t(image.height))
    fail(path, "pixel count does not match the image size");
  try {
    switch (format) {
      case ImageFormat::exr: return encode_exr(image, encoding);
      case ImageFormat::pfm: return encode_pfm(image);
      case ImageFormat::png: return encode_png(path, image, encoding);
    }
  } catch (const Error&) {
    throw;
  } catch (const std::exception& e) {
    fail(path, std::string("encoding failed: ") + e.what());
  }
  fail(path, "unknown image format");
}

void write_image(const std::string& path, const Image& image) {
  const std::string bytes = encode_image(path, image);
  write_file_atomically(path, bytes.data(), bytes.size());
}

Image read_image(const std::string& path, LdrEncoding ldr, ImageContent content) {
  return decode_image(path, read_file_as_stored(path), ldr, content);
}

void set_max_image_pixels(uint64_t pixels) { max_image_pixels() = pixels; }

std::optional<ByteImage> decode_image_bytes(const std::string& path, const std::string& bytes) {
  if (decoder_for(path, bytes) != Decoder::stb) return std::nullopt;
  // decode_stb's checks and errors, then the bytes its 8-bit table would have looked up.
  const StbInput in = checked_stb_input(path, bytes);
  if (stbi_is_hdr_from_memory(in.data, in.len) || stbi_is_16_bit_from_memory(in.data, in.len)) return std::nullopt;
  int w = 0, h = 0, n = 0;
  const StbBuffer<stbi_uc> px = load_8bit(path, in, &w, &h, &n);
  check_not_empty(path, w, h);
  ByteImage out;
  out.width = w;
  out.height = h;
  out.rgb.resize(size_t(w) * size_t(h) * 3);
  for (size_t i = 0; i < size_t(w) * size_t(h); ++i) {
    const stbi_uc* p = px.get() + i * size_t(n);
    for (int c = 0; c < 3; ++c) out.rgb[3 * i + size_t(c)] = p[n >= 3 ? c : 0];  // grey replicated, alpha dropped
  }
  return out;
}

std::optional<ByteImage> read_image_bytes(const std::string& path) { return decode_image_bytes(path, read_file_as_stored(path)); }

Image decode_image(const std::string& path, const std::string& bytes, LdrEncoding ldr, ImageContent content) {
  const Decoder decoder = decoder_for(path, bytes);
  Image image = decoder == Decoder::exr   ? decode_exr(path, bytes, content)
                : decoder == Decoder::pfm ? (content == ImageContent::scalar ? scalar_image(decode_pfm(path, bytes), {})
                                                                             : decode_pfm(path, bytes))
                                          : decode_stb(path, bytes, ldr, content);
  // stb accepts a Radiance header of height 0 (found by the image fuzzer): no image is empty.
  check_not_empty(path, image.width, image.height);
  return image;
}

}  // namespace pathspace
