// PLY reader: round trips of meshes the test writes itself in all three encodings (with quads,
// normals, uvs, extra properties and elements, gzip), and malformed files that must give a
// pathspace::Error naming the place (header line, or body offset / element index), never a crash.
#include <gtest/gtest.h>
#include <zlib.h>

#include <bit>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "pathspace/base/error.h"
#include "pathspace/io/ply_reader.h"
#include "support/temp_dir.h"

namespace pathspace {
namespace {

namespace fs = std::filesystem;

enum class Enc { ascii, le, be };

template <typename T>
void put(std::string* out, Enc e, T v) {
  if (e == Enc::ascii) {
    *out += std::to_string(v) + " ";
    return;
  }
  unsigned char b[sizeof(T)];
  std::memcpy(b, &v, sizeof(T));
  const bool swap = (e == Enc::be) == (std::endian::native == std::endian::little);
  if (swap)
    for (size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(b[i], b[sizeof(T) - 1 - i]);
  out->append(reinterpret_cast<const char*>(b), sizeof(T));
}

// A unit square (one quad) plus a triangle: 5 vertices, faces {0 1 2 3} and {1 4 2}. Vertices carry
// normals, uvs and an extra "confidence" double; an extra "edge" element follows the faces.
std::string square_ply(Enc e) {
  const char* fmt = e == Enc::ascii ? "ascii" : (e == Enc::le ? "binary_little_endian" : "binary_big_endian");
  std::string s = std::string("ply\nformat ") + fmt +
                  " 1.0\ncomment made by the test\nelement vertex 5\nproperty float x\nproperty float y\nproperty float z\n"
                  "property double confidence\nproperty float nx\nproperty float ny\nproperty float nz\n"
                  "property float s\nproperty float t\nelement face 2\nproperty list uchar int vertex_indices\n"
                  "property list uint8 float32 junk\nelement edge 1\nproperty int vertex1\nproperty int vertex2\nend_header\n";
  const float p[5][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {2, 0.5f, 0}};
  for (int i = 0; i < 5; ++i) {
    for (float c : p[i]) put(&s, e, c);
    put(&s, e, 0.25);
    put(&s, e, 0.f), put(&s, e, 0.f), put(&s, e, 1.f);
    put(&s, e, p[i][0] * 0.5f), put(&s, e, p[i][1]);
    if (e == Enc::ascii) s += "\n";
  }
  const int faces[2][4] = {{0, 1, 2, 3}, {1, 4, 2, -1}};
  for (int f = 0; f < 2; ++f) {
    const uint8_t n = f == 0 ? 4 : 3;
    put(&s, e, n);
    for (int k = 0; k < n; ++k) put(&s, e, int32_t(faces[f][k]));
    put(&s, e, uint8_t(2)), put(&s, e, 1.5f), put(&s, e, 2.5f);
    if (e == Enc::ascii) s += "\n";
  }
  put(&s, e, int32_t(0)), put(&s, e, int32_t(1));
  return s;
}

// One folder per test process (ctest runs the cases as parallel processes).
const fs::path& test_dir() {
  static const pathspace::testing::TempDir dir("ply");
  return dir.path;
}

std::string temp_file(const std::string& name, const std::string& bytes) {
  const std::string path = (test_dir() / name).string();
  std::ofstream(path, std::ios::binary) << bytes;
  return path;
}

void expect_square(const PlyMesh& m) {
  ASSERT_EQ(m.positions.size(), 5u);
  EXPECT_EQ(m.positions[4], Vec3(2, 0.5f, 0));
  ASSERT_EQ(m.normals.size(), 5u);
  EXPECT_EQ(m.normals[3], Vec3(0, 0, 1));
  ASSERT_EQ(m.uvs.size(), 5u);
  EXPECT_EQ(m.uvs[2][0], 0.5f);
  EXPECT_EQ(m.uvs[2][1], 1.f);
  const std::vector<uint32_t> expected = {0, 1, 2, 0, 2, 3, 1, 4, 2};  // the quad fan-triangulated
  EXPECT_EQ(m.indices, expected);
  EXPECT_EQ(m.polygon_faces, 1u);
}

TEST(PlyReader, RoundTripAllEncodings) {
  for (Enc e : {Enc::ascii, Enc::le, Enc::be}) {
    SCOPED_TRACE(int(e));
    expect_square(read_ply(temp_file("square" + std::to_string(int(e)) + ".ply", square_ply(e))));
  }
}

TEST(PlyReader, GzipAndCrLfHeader) {
  std::string text = square_ply(Enc::le);
  const size_t end = text.find("end_header\n");
  std::string header = text.substr(0, end), crlf;
  for (char c : header) crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
  text = crlf + "end_header\r\n" + text.substr(end + 11);
  const std::string path = (test_dir() / "square.ply.gz").string();
  gzFile f = gzopen(path.c_str(), "wb");
  ASSERT_NE(f, nullptr);
  ASSERT_EQ(gzwrite(f, text.data(), unsigned(text.size())), int(text.size()));
  gzclose(f);
  expect_square(read_ply(path));
}

// The error message, or "" when no Error was thrown.
std::string error_of(const std::string& bytes, FileLoc* loc = nullptr) {
  try {
    parse_ply(bytes, "bad.ply");
  } catch (const Error& e) {
    if (loc) *loc = e.location();
    return e.what();
  }
  return "";
}

TEST(PlyReader, TruncatedBinaryBodyNamesOffsetAndElement) {
  for (Enc e : {Enc::le, Enc::be}) {
    const std::string full = square_ply(e);
    // Cut inside the face element; the reader must stop at the end of the data.
    const std::string msg = error_of(full.substr(0, full.size() - 30));
    EXPECT_NE(msg.find("truncated"), std::string::npos) << msg;
    EXPECT_NE(msg.find("byte offset"), std::string::npos) << msg;
    EXPECT_NE(msg.find("element 'face' #1"), std::string::npos) << msg;
  }
  const std::string ascii = square_ply(Enc::ascii);
  EXPECT_NE(error_of(ascii.substr(0, ascii.size() / 2)).find("truncated"), std::string::npos);
}

TEST(PlyReader, BadIndexUnknownTypeNaNAndHugeCounts) {
  std::string s = square_ply(Enc::ascii);
  const size_t face = s.find("4 0 1 2 3");
  ASSERT_NE(face, std::string::npos);
  std::string bad = s;
  bad.replace(face, 9, "4 0 1 2 9");
  EXPECT_NE(error_of(bad).find("vertex index 9 out of range"), std::string::npos) << error_of(bad);

  FileLoc loc;
  bad = s;
  bad.replace(bad.find("property float ny"), 17, "property half ny");
  EXPECT_NE(error_of(bad, &loc).find("unknown property type 'half'"), std::string::npos);
  EXPECT_EQ(loc.line, 10);  // header line of the bad property
  EXPECT_EQ(loc.file, "bad.ply");

  bad = s;
  const size_t body = bad.find("end_header\n") + 11;
  bad.replace(body, 8, "nan");  // the first coordinate, written as "0.000000"
  FileLoc nan_loc;
  EXPECT_NE(error_of(bad, &nan_loc).find("NaN"), std::string::npos) << error_of(bad);
  EXPECT_GT(nan_loc.line, 0);

  bad = square_ply(Enc::le);
  bad.replace(bad.find("element vertex 5"), 16, "element vertex 4000000000");
  EXPECT_NE(error_of(bad).find("exceeds the data"), std::string::npos) << error_of(bad);

  EXPECT_NE(error_of("ply\nformat ascii 1.0\nelement vertex 1\n").find("end_header"), std::string::npos);
  EXPECT_NE(error_of("PLY?\n").find("not a PLY"), std::string::npos);
  EXPECT_NE(error_of("").find("not a PLY"), std::string::npos);
}

TEST(PlyReader, MissingFileIsAnError) { EXPECT_THROW(read_ply("/nonexistent/mesh.ply"), Error); }

}  // namespace
}  // namespace pathspace
