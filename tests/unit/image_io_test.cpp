// Unit tests: sRGB transfer values, EXR/PFM bit-exact round trips (non-finite values included), PNG
// round trip within one 8-bit step, PFM bottom-up row order against hand-written bytes, atomic
// writes (no half-written target, no leftover temporary) and errors for truncated files.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include <signal.h>
#include <sys/resource.h>
#include <unistd.h>

#include "pathspace/base/error.h"
#include "pathspace/film/tonemap.h"
#include "pathspace/io/image_io.h"
#include "support/temp_dir.h"

namespace pathspace {
namespace {

namespace fs = std::filesystem;

using pathspace::testing::TempDir;

std::string read_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void write_bytes(const std::string& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary);
  out.write(bytes.data(), std::streamsize(bytes.size()));
}

std::string f32_bytes(float v, bool little_endian) {
  const uint32_t bits = std::bit_cast<uint32_t>(v);
  std::string s(4, '\0');
  for (int i = 0; i < 4; ++i) s[little_endian ? i : 3 - i] = char((bits >> (8 * i)) & 0xffu);
  return s;
}

// Distinct values per pixel and channel, negatives, a denormal and non-finite values at known spots.
Image test_image(int w, int h) {
  Image img(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) img.at(x, y) = Rgb(float(x) + 0.125f * float(y), -0.5f * float(x * y), 1e3f * float(y) + 1e-3f);
  img.at(1, 2).g = std::numeric_limits<float>::quiet_NaN();
  img.at(3, 0).r = std::numeric_limits<float>::infinity();
  img.at(0, h - 1).b = -std::numeric_limits<float>::infinity();
  img.at(2, 1).r = std::numeric_limits<float>::denorm_min();
  img.at(w - 1, h - 1) = Rgb(-0.f, 3.4e38f, -1e-20f);
  return img;
}

void expect_bit_exact(const Image& a, const Image& b) {
  ASSERT_EQ(a.width, b.width);
  ASSERT_EQ(a.height, b.height);
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x)
      for (int c = 0; c < 3; ++c)
        ASSERT_EQ(std::bit_cast<uint32_t>(a.at(x, y)[c]), std::bit_cast<uint32_t>(b.at(x, y)[c]))
            << "pixel (" << x << ", " << y << ") channel " << c;
}

// Expects read_image to throw a pathspace::Error whose message names the file (and `what`, if given).
void expect_read_error(const std::string& path, const std::string& what = {}) {
  try {
    read_image(path);
    ADD_FAILURE() << "no error reading " << path;
  } catch (const Error& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find(path), std::string::npos) << msg;
    if (!what.empty()) {
      EXPECT_NE(msg.find(what), std::string::npos) << msg;
    }
  }
}

TEST(Tonemap, SrgbKnownValues) {
  EXPECT_EQ(srgb_from_linear(0.f), 0.f);
  EXPECT_NEAR(srgb_from_linear(1.f), 1.f, 1e-6f);
  EXPECT_NEAR(srgb_from_linear(0.5f), 0.7353569831f, 1e-6f);
  EXPECT_NEAR(srgb_from_linear(0.18f), 0.4613561f, 1e-6f);
  EXPECT_NEAR(srgb_from_linear(0.001f), 0.01292f, 1e-8f);  // linear segment
  EXPECT_EQ(linear_from_srgb(0.f), 0.f);
  EXPECT_NEAR(linear_from_srgb(1.f), 1.f, 1e-6f);
  EXPECT_NEAR(linear_from_srgb(0.7353569831f), 0.5f, 1e-6f);
  // The two segments meet at 0.0031308 (0.04045 encoded) to within float precision.
  const float t = 0.0031308f;
  EXPECT_NEAR(srgb_from_linear(t), srgb_from_linear(std::nextafter(t, 1.f)), 1e-6f);
  EXPECT_NEAR(srgb_from_linear(t), 0.04045f, 1e-6f);
  EXPECT_NEAR(linear_from_srgb(0.04045f), linear_from_srgb(std::nextafter(0.04045f, 1.f)), 1e-7f);
  for (int i = 0; i <= 1000; ++i) {
    const float v = float(i) / 1000.f;
    EXPECT_NEAR(linear_from_srgb(srgb_from_linear(v)), v, 1e-6f);
  }
}

TEST(Tonemap, Srgb8ClampsAndRounds) {
  EXPECT_EQ(to_srgb8(0.f), 0);
  EXPECT_EQ(to_srgb8(1.f), 255);
  EXPECT_EQ(to_srgb8(0.5f), 188);  // 0.7353570 * 255 = 187.52
  EXPECT_EQ(to_srgb8(-1.f), 0);
  EXPECT_EQ(to_srgb8(7.f), 255);
  EXPECT_EQ(to_srgb8(std::numeric_limits<float>::quiet_NaN()), 0);
  EXPECT_EQ(to_srgb8(std::numeric_limits<float>::infinity()), 255);
  EXPECT_EQ(to_srgb8(-std::numeric_limits<float>::infinity()), 0);
  EXPECT_EQ(to_srgb8(0.25f, 2.f), to_srgb8(0.5f));  // exposure multiplies first
  for (int i = 0; i < 256; ++i) EXPECT_EQ(to_srgb8(linear_from_srgb(float(i) / 255.f)), i);
}

TEST(ImageIo, FormatFromPath) {
  EXPECT_EQ(image_format_from_path("a/b.exr"), ImageFormat::exr);
  EXPECT_EQ(image_format_from_path("B.EXR"), ImageFormat::exr);
  EXPECT_EQ(image_format_from_path("x.Pfm"), ImageFormat::pfm);
  EXPECT_EQ(image_format_from_path("out.PNG"), ImageFormat::png);
  for (const char* bad : {"a.jpg", "noext", "a.exr.tmp", "dir.png/file"}) {
    try {
      image_format_from_path(bad);
      ADD_FAILURE() << bad;
    } catch (const Error& e) {
      const std::string msg = e.what();
      EXPECT_NE(msg.find(".exr"), std::string::npos) << msg;
      EXPECT_NE(msg.find(".png"), std::string::npos) << msg;
      EXPECT_NE(msg.find(bad), std::string::npos) << msg;
    }
  }
}

TEST(ImageIo, ExrAndPfmRoundTripBitExact) {
  TempDir dir;
  const Image img = test_image(6, 5);
  for (const char* name : {"a.exr", "a.pfm", "UPPER.EXR"}) {
    SCOPED_TRACE(name);
    write_image(dir.file(name), img);
    expect_bit_exact(img, read_image(dir.file(name)));
  }
  // One-pixel images work too.
  Image one(1, 1);
  one.at(0, 0) = Rgb(-2.f, 0.5f, std::numeric_limits<float>::quiet_NaN());
  write_image(dir.file("one.exr"), one);
  write_image(dir.file("one.pfm"), one);
  expect_bit_exact(one, read_image(dir.file("one.exr")));
  expect_bit_exact(one, read_image(dir.file("one.pfm")));
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{"UPPER.EXR", "a.exr", "a.pfm", "one.exr", "one.pfm"}));
}

TEST(ImageIo, PngRoundTripWithinOneStep) {
  TempDir dir;
  Image img(17, 9);
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(0.f, 1.f);
  for (Rgb& p : img.pixels) p = Rgb(u(rng), u(rng) * u(rng), u(rng) * 0.01f);
  img.at(0, 0) = Rgb(std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity(), -3.f);
  img.at(1, 0) = Rgb(1.f, 2.f, 0.f);
  write_image(dir.file("a.png"), img);
  const Image back = read_image(dir.file("a.png"));
  ASSERT_EQ(back.width, 17);
  ASSERT_EQ(back.height, 9);
  for (size_t i = 2; i < img.size(); ++i)
    for (int c = 0; c < 3; ++c)
      ASSERT_NEAR(srgb_from_linear(back.pixels[i][c]), srgb_from_linear(img.pixels[i][c]), 0.5f / 255.f + 1e-5f) << i;
  EXPECT_EQ(back.at(0, 0), Rgb(0.f, 1.f, 0.f));  // NaN -> 0, +Inf -> 1, negative -> 0
  EXPECT_EQ(back.at(1, 0), Rgb(1.f, 1.f, 0.f));
}

TEST(ImageIo, PfmRowsAreStoredBottomUp) {
  TempDir dir;
  Image img(2, 3);
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 2; ++x) img.at(x, y) = Rgb(float(10 * y + x), 0.f, 0.f);
  write_image(dir.file("o.pfm"), img);
  const std::string bytes = read_bytes(dir.file("o.pfm"));
  const std::string header = "PF\n2 3\n-1.0\n";
  ASSERT_EQ(bytes.size(), header.size() + 2 * 3 * 12);
  EXPECT_EQ(bytes.substr(0, header.size()), header);
  EXPECT_EQ(bytes.substr(header.size(), 4), f32_bytes(20.f, true));  // first stored pixel: bottom-left
  EXPECT_EQ(bytes.substr(bytes.size() - 12, 4), f32_bytes(1.f, true));  // last stored: top-right
  const Image back = read_image(dir.file("o.pfm"));
  EXPECT_EQ(back.at(0, 0), img.at(0, 0));
  EXPECT_EQ(back.at(1, 2), img.at(1, 2));
}

TEST(ImageIo, HandWrittenPfmFiles) {
  TempDir dir;
  // Colour, little endian: bottom row (1,2,3) (4,5,6), then top row (7,8,9) (10,11,12).
  std::string colour = "PF\n2 2\n-1.0\n";
  for (int i = 1; i <= 12; ++i) colour += f32_bytes(float(i), true);
  write_bytes(dir.file("c.pfm"), colour);
  const Image c = read_image(dir.file("c.pfm"));
  ASSERT_EQ(c.width, 2);
  ASSERT_EQ(c.height, 2);
  EXPECT_EQ(c.at(0, 0), Rgb(7, 8, 9));
  EXPECT_EQ(c.at(1, 0), Rgb(10, 11, 12));
  EXPECT_EQ(c.at(0, 1), Rgb(1, 2, 3));
  EXPECT_EQ(c.at(1, 1), Rgb(4, 5, 6));

  // Grey, big endian (positive scale), one column, other whitespace in the header.
  const std::string grey = "Pf 1\t2\r\n1.0\n" + f32_bytes(0.25f, false) + f32_bytes(-2.f, false);
  write_bytes(dir.file("g.pfm"), grey);
  const Image g = read_image(dir.file("g.pfm"));
  ASSERT_EQ(g.width, 1);
  ASSERT_EQ(g.height, 2);
  EXPECT_EQ(g.at(0, 0), Rgb(-2.f));
  EXPECT_EQ(g.at(0, 1), Rgb(0.25f));

  // |scale| != 1 scales the values.
  write_bytes(dir.file("s.pfm"), "Pf\n1 1\n-4.0\n" + f32_bytes(0.5f, true));
  EXPECT_EQ(read_image(dir.file("s.pfm")).at(0, 0), Rgb(2.f));
}

TEST(ImageIo, MalformedPfm) {
  TempDir dir;
  const std::string px = f32_bytes(1.f, true);
  const std::pair<std::string, std::string> cases[] = {
      {"P6\n1 1\n255\nabc", "bad PFM header"},
      {"PF\n0 1\n-1.0\n" + px, "bad PFM header"},
      {"PF\n-1 1\n-1.0\n" + px, "bad PFM header"},
      {"PF\n1 x\n-1.0\n" + px, "bad PFM header"},
      {"PF\n1 1\n0\n" + px, "bad PFM header"},
      {"PF\n1 1\nnan\n" + px, "bad PFM header"},
      {"PF\n1 1\n", "bad PFM header"},
      {"PF\n1 1\n-1.0", "bad PFM header"},
      {"PF\n99999999999 1\n-1.0\n", "bad PFM header"},
      {"PF\n2 2\n-1.0\n" + px, "truncated data: expected 48 bytes"},
      {"Pf\n2 1\n-1.0\n" + px, "truncated data: expected 8 bytes"},
  };
  for (const auto& [bytes, what] : cases) {
    SCOPED_TRACE(bytes);
    write_bytes(dir.file("bad.pfm"), bytes);
    expect_read_error(dir.file("bad.pfm"), what);
  }
}

TEST(ImageIo, TruncatedFilesThrow) {
  TempDir dir;
  const Image img = test_image(40, 30);
  for (const char* name : {"t.exr", "t.pfm", "t.png"}) {
    SCOPED_TRACE(name);
    write_image(dir.file(name), img);
    const std::string full = read_bytes(dir.file(name));
    // stb ignores PNG checksums, so a PNG missing only the end chunk still decodes: cut more.
    const size_t cut = std::string(name) == "t.png" ? 13 : 1;
    for (size_t len : {size_t(0), size_t(3), size_t(20), full.size() / 2, full.size() - cut}) {
      write_bytes(dir.file(name), full.substr(0, len));
      expect_read_error(dir.file(name));
    }
  }
  expect_read_error(dir.file("missing.exr"), "file not found");
}

// decode_image(name, bytes) throws an Error whose message contains `message`.
void expect_decode_error(const std::string& name, const std::string& bytes, const std::string& message) {
  try {
    decode_image(name, bytes);
    ADD_FAILURE() << "no error for " << name;
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
  }
}

// A PNG chunk that declares more bytes than the file holds is an error before stb sees it: stb
// would first grow its buffer to the declared length (1.4 GB here; found by the image fuzzer).
TEST(ImageIo, PngChunkLongerThanTheFileIsAnError) {
  TempDir dir;
  write_image(dir.file("t.png"), test_image(40, 30));
  std::string bytes = read_bytes(dir.file("t.png"));
  const size_t idat = bytes.find("IDAT");
  ASSERT_NE(idat, std::string::npos);
  bytes.replace(idat - 4, 4, "\x52\x72\x8d\x0d");
  expect_decode_error("t.png", bytes, "declares 1383238925 bytes, more than the file holds");
}

// A JPEG Huffman table whose 16 code counts sum to more than 256 is an error before stb sees it:
// stb would write past its table (found by the image fuzzer).
TEST(ImageIo, JpegHuffmanTableWithTooManyCodesIsAnError) {
  std::string jpeg = "\xff\xd8\xff\xc4";
  jpeg += std::string("\x00\x14", 2);           // segment length 20: one table
  jpeg += std::string("\x00", 1);                // class 0, id 0
  jpeg += std::string(15, '\0') + "\xff";       // 16 counts: 255 codes of length 16 ...
  jpeg[jpeg.size() - 2] = '\x02';                // ... and 2 of length 15: 257
  jpeg += std::string(257, '\x01') + "\xff\xd9";
  expect_decode_error("t.jpg", jpeg, "declares 257 codes (at most 256)");
  expect_decode_error("t.jpg", "\xff" + jpeg, "declares 257 codes (at most 256)");  // after a fill byte, which stb skips
}

TEST(ImageIo, RefusesEmptyImagesAndMissingDirectories) {
  TempDir dir;
  EXPECT_THROW(write_image(dir.file("e.exr"), Image()), Error);
  EXPECT_THROW(write_image(dir.file("e.png"), Image(0, 4)), Error);
  const std::string missing = dir.file("no/such/dir/a.exr");
  try {
    write_image(missing, test_image(4, 5));
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find(missing), std::string::npos) << msg;
    EXPECT_NE(msg.find("does not exist"), std::string::npos) << msg;
  }
  EXPECT_TRUE(dir.entries().empty());
}

TEST(ImageIo, OverwriteReplacesTheFile) {
  TempDir dir;
  const std::string path = dir.file("r.pfm");
  write_bytes(path, "old contents that are not an image");
  Image a = test_image(5, 5), b(3, 2);
  b.at(2, 1) = Rgb(1.f, 2.f, 3.f);
  write_image(path, a);
  expect_bit_exact(a, read_image(path));
  write_image(path, b);
  expect_bit_exact(b, read_image(path));
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"r.pfm"});
}

TEST(ImageIo, FailedWritesLeaveNoTemporaryFile) {
  TempDir dir;
  const Image img = test_image(4, 5);
  // The parent is a regular file: refused before anything is created.
  write_bytes(dir.file("plain"), "x");
  EXPECT_THROW(write_image(dir.file("plain/a.png"), img), Error);
  // The target is a directory: it cannot be replaced, and nothing is left next to it.
  fs::create_directory(dir.path / "taken.exr");
  try {
    write_image(dir.file("taken.exr"), img);
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(dir.file("taken.exr")), std::string::npos) << e.what();
  }
  EXPECT_TRUE(fs::is_empty(dir.path / "taken.exr"));
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{"plain", "taken.exr"}));
  EXPECT_EQ(read_bytes(dir.file("plain")), "x");
}

// A write that fails half way (file size limit, works as root too) keeps the old target intact and
// removes its temporary file.
TEST(ImageIo, WriteFailingHalfWayKeepsTheOldFile) {
  TempDir dir;
  const std::string path = dir.file("k.pfm");
  const Image small = test_image(5, 5);
  write_image(path, small);
  const std::string before = read_bytes(path);

  rlimit old_limit{};
  ASSERT_EQ(getrlimit(RLIMIT_FSIZE, &old_limit), 0);
  rlimit limit = old_limit;
  limit.rlim_cur = 4096;  // the 100x100 image needs 120 kB
  void (*old_handler)(int) = signal(SIGXFSZ, SIG_IGN);  // fail with EFBIG instead of a signal
  ASSERT_EQ(setrlimit(RLIMIT_FSIZE, &limit), 0);
  bool threw = false;
  try {
    write_image(path, Image(100, 100));
  } catch (const Error& e) {
    threw = true;
    EXPECT_NE(std::string(e.what()).find("cannot write '" + path + "': "), std::string::npos) << e.what();
  }
  setrlimit(RLIMIT_FSIZE, &old_limit);
  signal(SIGXFSZ, old_handler);

  EXPECT_TRUE(threw);
  EXPECT_EQ(read_bytes(path), before);
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"k.pfm"});
}

}  // namespace
}  // namespace pathspace
