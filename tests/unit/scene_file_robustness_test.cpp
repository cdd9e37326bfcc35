// Malformed scene files found by hand or by the fuzzers (tests/fuzz/): each must give a
// pathspace::Error (or a warning, where docs/scene-files.md says so) that names file:line, never a
// crash, a hang or undefined behaviour. Fuzzer finds are named after what they broke.
#include <gtest/gtest.h>

#include <fstream>

#include "pathspace/io/pbrt/pbrt_scene_builder.h"
#include "pathspace/io/ply_reader.h"
#include "pathspace/io/scene_loader.h"
#include "support/temp_dir.h"

namespace pathspace {
namespace {

using pathspace::testing::TempDir;

// The Error thrown by `f` (an empty location when none was thrown).
template <typename F>
Error error_of(F&& f) {
  try {
    f();
  } catch (const Error& e) {
    return e;
  }
  return Error("no error");
}

Error pbrt_error(const std::string& text, std::vector<std::string>* warnings = nullptr) {
  return error_of([&] {
    LoadWarnings w(warnings);
    pbrt::load_pbrt_string(text, "t.pbrt", "", {}, &w, nullptr);
  });
}

bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

TEST(PbrtRobustness, NonFiniteNumbersAreErrorsAtTheirToken) {
  for (const char* bad : {"nan", "inf", "-inf", "NaN", "infinity", "1e39", "-1e300"}) {
    SCOPED_TRACE(bad);
    const Error e = pbrt_error(std::string("WorldBegin\nShape \"sphere\" \"float radius\" [ ") + bad + " ]\n");
    EXPECT_EQ(e.location().to_string(), "t.pbrt:2:33");
    EXPECT_TRUE(contains(e.what(), "not finite or out of the float range")) << e.what();
  }
  EXPECT_EQ(pbrt_error("WorldBegin\nTranslate 0 nan 0\n").location().to_string(), "t.pbrt:2:13");
  EXPECT_EQ(pbrt_error("WorldBegin\nShape \"trianglemesh\" \"point3 P\" [ 0 0 0 1 0 0 0 inf 0 ]\n").location().line, 2);
}

// Found reading the parser before fuzzing: integers beyond int64 were converted before the range
// check (undefined behaviour; UBSan float-cast-overflow), and 32-bit overflow in get_int.
TEST(PbrtRobustness, IntegersOutsideThe32BitRangeAreErrors) {
  for (const char* bad : {"1e12", "-3e9", "1e30", "2.5"}) {
    SCOPED_TRACE(bad);
    const Error e = pbrt_error(std::string("Film \"rgb\" \"integer xresolution\" ") + bad + "\nWorldBegin\n");
    EXPECT_EQ(e.location().to_string(), "t.pbrt:1:12");
    EXPECT_TRUE(contains(e.what(), "32-bit range")) << e.what();
  }
}

TEST(PbrtRobustness, UnknownMaterialTypeWarnsWithLocation) {
  std::vector<std::string> w;
  LoadWarnings lw(&w);
  const Scene s = pbrt::load_pbrt_string("WorldBegin\nMaterial \"velvet\" \"float sheen\" 2\nShape \"sphere\"\n", "t.pbrt", "", {}, &lw, nullptr);
  ASSERT_EQ(s.spheres.size(), 1u);
  EXPECT_EQ(s.materials[s.spheres[0].material].diffuse, Rgb(0.5f));
  bool found = false;
  for (const std::string& m : w) found |= contains(m, "t.pbrt:2:1: warning: material type 'velvet' not supported");
  EXPECT_TRUE(found);
  // As a named material's type too.
  w.clear();
  LoadWarnings lw2(&w);  // a fresh collector: LoadWarnings keeps identical messages once
  pbrt::load_pbrt_string("WorldBegin\nMakeNamedMaterial \"m\" \"string type\" \"velvet\"\n", "t.pbrt", "", {}, &lw2, nullptr);
  ASSERT_FALSE(w.empty());
  EXPECT_TRUE(contains(w[0], "t.pbrt:2:1: warning: material type 'velvet'")) << w[0];
}

// Found while writing these tests: a null warnings pointer crashed on the first warning.
// Two infinite lights reached Scene::finalize, whose Error named no file; constant environments
// add up exactly, so they are merged.
TEST(PbrtRobustness, TwoConstantEnvironmentsAddUpAndNullWarningsAreDiscarded) {
  const Scene s = pbrt::load_pbrt_string("WorldBegin\nLightSource \"infinite\" \"rgb L\" [ 1 2 3 ]\nLightSource \"infinite\" \"float scale\" 2\n",
                                         "t.pbrt", "", {}, nullptr, nullptr);
  ASSERT_EQ(s.lights.size(), 1u);
  EXPECT_EQ(s.lights[0].value, Rgb(3, 4, 5));
}

TEST(PbrtRobustness, MissingIncludeNamesFileAndLine) {
  const TempDir dir("robust");
  std::ofstream(dir.file("main.pbrt")) << "WorldBegin\nShape \"sphere\"\n  Include \"sub/gone.pbrt\"\n";
  const Error e = error_of([&] { load_scene(dir.file("main.pbrt"), {}, nullptr); });
  EXPECT_EQ(e.location().to_string(), dir.file("main.pbrt") + ":3:3");
  EXPECT_TRUE(contains(e.what(), "sub/gone.pbrt")) << e.what();
}

TEST(PlyReaderRobustness, TruncatedAsciiNamesLineAndElement) {
  const std::string ply = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                          "element face 1\nproperty list uchar int vertex_indices\nend_header\n0.000 0.000 0.000\n1.000 0.000 0.000\n0.000 1.000";
  const Error e = error_of([&] { parse_ply(ply, "cut.ply"); });
  EXPECT_EQ(e.location().to_string(), "cut.ply:12");
  EXPECT_TRUE(contains(e.what(), "truncated")) << e.what();
  EXPECT_TRUE(contains(e.what(), "element 'vertex' #2")) << e.what();
}

TEST(PlyReaderRobustness, TruncatedBinaryNamesFileAndOffset) {
  std::string ply = "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                    "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
  ply += std::string(3 * 12, '\0') + "\x03";  // the face's index list is cut off after its count
  const Error e = error_of([&] { parse_ply(ply, "cut.ply"); });
  EXPECT_EQ(e.location().file, "cut.ply");
  EXPECT_TRUE(contains(e.what(), "truncated")) << e.what();
  EXPECT_TRUE(contains(e.what(), "byte offset")) << e.what();
}

TEST(PlyReaderRobustness, NegativeAndOutOfRangeFaceIndices) {
  const std::string head = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                           "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n";
  for (const char* face : {"3 0 1 -1", "3 0 1 3", "3 0 1 4294967296"}) {
    SCOPED_TRACE(face);
    const Error e = error_of([&] { parse_ply(head + face + "\n", "f.ply"); });
    EXPECT_EQ(e.location().to_string(), "f.ply:13");
    EXPECT_TRUE(contains(e.what(), "out of range")) << e.what();
  }
}

// Fuzzer find (UBSan): an ascii face index of 6.7e71 passed the integer check and overflowed the
// conversion in the error message. Ascii integers must now fit their declared type.
TEST(PlyReaderRobustness, AsciiIntegersOutsideTheirTypeAreErrors) {
  const std::string head = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                           "property uchar flag\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
  for (const std::string& body : {std::string("0 0 0 256\n1 0 0 0\n0 1 0 0\n3 0 1 2\n"),
                                  std::string("0 0 0 0\n1 0 0 0\n0 1 0 0\n3 0 1 666666666666666666666666666666666666666666666666666666666666666666666666\n"),
                                  std::string("0 0 0 0\n1 0 0 0\n0 1 0 0\n3 0 1 -2147483649\n")}) {
    const Error e = error_of([&] { parse_ply(head + body, "r.ply"); });
    EXPECT_TRUE(contains(e.what(), "out of range for its integer type")) << e.what();
    EXPECT_GT(e.location().line, 10);
  }
}

// Found reading the reader before fuzzing: an element without properties and a count near 2^64
// looped forever (nothing bounds the count when instances occupy no bytes).
TEST(PlyReaderRobustness, EmptyElementWithHugeCountIsSkipped) {
  const std::string ply = "ply\nformat binary_little_endian 1.0\nelement nothing 18446744073709551615\nelement vertex 0\n"
                          "property float x\nproperty float y\nproperty float z\nelement face 0\n"
                          "property list uchar int vertex_indices\nend_header\n";
  const PlyMesh m = parse_ply(ply, "e.ply");
  EXPECT_TRUE(m.positions.empty());
}

// tinyobjloader reports bad indices without a line (or not at all); the loader's own scan names it.
TEST(ObjLoaderRobustness, BadFaceIndicesAreErrorsAtTheirLine) {
  const TempDir dir("robust");
  for (const char* face : {"f 1 2 9", "f 1/1 2/1 -4/1", "f 0 1 2", "f 1//1 2//1 99999999999999999999"}) {
    SCOPED_TRACE(face);
    std::ofstream(dir.file("bad.obj"), std::ios::trunc) << "v 0 0 0\nv 1 0 0\n# comment\nv 0 1 0\n" << face << "\nv 1 1 1\n";
    const Error e = error_of([&] { load_scene(dir.file("bad.obj"), {}, nullptr); });
    EXPECT_EQ(e.location().to_string(), dir.file("bad.obj") + ":5:1") << e.what();
  }
  for (const char* v : {"v nan 0 0", "v 0 inf 0", "v 0 0 1e39", "v 0 x 0"}) {  // tinyobjloader would read 0
    SCOPED_TRACE(v);
    std::ofstream(dir.file("bad.obj"), std::ios::trunc) << "v 0 0 0\nv 1 0 0\n" << v << "\nf 1 2 3\n";
    EXPECT_EQ(error_of([&] { load_scene(dir.file("bad.obj"), {}, nullptr); }).location().to_string(), dir.file("bad.obj") + ":3:1");
  }
  // A positive index may name a vertex defined further down; a negative one only those above.
  std::ofstream(dir.file("later.obj"), std::ios::trunc) << "v 0 0 0\nv 1 0 0\nf 1 2 3\nv 0 1 0\nf -1 -2 -3\n";
  EXPECT_EQ(load_scene(dir.file("later.obj"), {}, nullptr).triangles.size(), 2u);
}

}  // namespace
}  // namespace pathspace
