// Robustness (issue 17): for each kind of bad input, the real binary exits with the documented status
// (2 usage, 1 bad input; docs/cli.md "Exit codes and errors"), the message names the cause, and no
// file in the test's folder changes except the requested outputs (contents and modes before and after).
// Kinds: values that crashed Embree, outputs that overwrite each other or an input, numbers that
// wrapped or were ignored, and misleading messages.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <string>

#include "robustness_fixture.h"
#include "support/gltf_test_files.h"

namespace pathspace::testing {
namespace {

// --- values Embree aborted on (SIGABRT in ray.valid()) ---

TEST_F(Robustness, HugeLensRadiusIsAUsageError) {
  expect(std::string("render cornell-box --lens-radius 1e20 --focus-distance 1 -o a.exr") + kQuick, 2, {"--lens-radius", "1e20"});
}

TEST_F(Robustness, HugePbrtGeometryIsAnInputError) {
  // The message points at the Shape statement (lines 1-4 camera, 5 light).
  const std::map<std::string, std::pair<std::string, std::string>> shapes = {
      {"radius", {"Shape \"sphere\" \"float radius\" 1e20\n", "huge.pbrt:6:1: "}},
      {"translate", {"Translate 1e20 0 0\nShape \"sphere\"\n", "huge.pbrt:7:1: "}},
      {"scale", {"Scale 1e20 1e20 1e20\nShape \"sphere\"\n", "huge.pbrt:7:1: "}},
      {"coordinates", {"Shape \"trianglemesh\" \"point3 P\" [ 0 0 0  1e20 0 0  0 1 0 ] \"integer indices\" [ 0 1 2 ]\n", "huge.pbrt:6:1: "}}};
  for (const auto& [what, shape] : shapes) {
    SCOPED_TRACE(what);
    write("huge.pbrt", std::string(kCamera) + kLight + shape.first);
    expect(std::string("render huge.pbrt -o a.exr") + kQuick, 1, {shape.second, "outside the supported range"});
  }
}

TEST_F(Robustness, InvalidMaterialIsAnInputError) {
  write("neg.pbrt", std::string(kCamera) + kLight + "Material \"diffuse\" \"rgb reflectance\" [ -0.5 0.5 0.5 ]\nShape \"sphere\"\n");
  expect(std::string("render neg.pbrt -o a.exr") + kQuick, 1, {"neg.pbrt:6:1: ", "diffuse reflectance", "-0.5", ">= 0"});
}

// "--" ends option parsing: a scene whose name starts with '-' follows it, also right after -o's list.
TEST_F(Robustness, DoubleDashEndsOptionParsing) {
  write("-odd.pbrt", std::string(kCamera) + kLight + "Shape \"sphere\"\n");
  expect("render -r 8x8 -s 1 -q -o a.exr -- -odd.pbrt", 0, {}, {"a.exr"});
  expect("render -r 8x8 -s 1 -q -o a.exr b.exr -- -odd.pbrt", 0, {}, {"a.exr", "b.exr"});
  expect("render -r 8x8 -o c.exr -s 1 -q -- -odd.pbrt", 0, {}, {"c.exr"});
  expect("render -o d.exr -- -odd.pbrt -s 1", 2, {"not expected"});  // options after "--" are words
}

// Out of memory is said in words, not as "std::bad_alloc" (prlimit caps the address space).
TEST_F(Robustness, OutOfMemoryIsSaidInWords) {
  if (std::system("prlimit --version > /dev/null 2>&1") != 0) GTEST_SKIP() << "no prlimit";
  const std::string cmd = "prlimit --as=1500000000 '" PATHSPACE_BINARY "' render cornell-box -r 16384x16384 -s 1 -q -o " +
                          dir.file("big.exr") + " 2>&1";
  std::string out;
  FILE* p = popen(cmd.c_str(), "r");
  ASSERT_NE(p, nullptr);
  char buf[4096];
  for (size_t n; (n = fread(buf, 1, sizeof buf, p)) > 0;) out.append(buf, n);
  const int status = pclose(p);
  EXPECT_EQ(WIFEXITED(status) ? WEXITSTATUS(status) : -1, 1) << out;
  EXPECT_NE(out.find("error: out of memory (the image size"), std::string::npos) << out;
  EXPECT_FALSE(fs::exists(dir.file("big.exr")));
}

// A scene file's own sample count is held to --spp's range: it is what the render runs when -s is
// not given.
TEST_F(Robustness, SceneSampleCountHasTheRangeOfSpp) {
  write("many.pbrt", std::string("Sampler \"halton\" \"integer pixelsamples\" 100000000\n") + kCamera + kLight + "Shape \"sphere\"\n");
  expect("render many.pbrt -o a.exr -r 8x8 -q", 1, {"many.pbrt:1:1: ", "pixelsamples must be between 1 and 16777216"});
}

// render -D NAME=VALUE: Mitsuba parameters from the command line; misuse is a usage error.
TEST_F(Robustness, SceneParametersFromTheCommandLine) {
#if PATHSPACE_HAS_MITSUBA
  write("p.xml",
        "<scene version=\"3.0.0\">\n"
        "  <emitter type=\"point\"><point name=\"position\" x=\"0\" y=\"0\" z=\"4\"/><rgb name=\"intensity\" value=\"$power\"/></emitter>\n"
        "  <shape type=\"sphere\"/>\n"
        "</scene>\n");
  expect(std::string("render p.xml -o a.exr") + kQuick, 1, {"p.xml:2:", "undefined parameter '$power'", "-D power=VALUE"});
  expect(std::string("render p.xml -D power -o a.exr") + kQuick, 2, {"expected NAME=VALUE", "power"});
  expect(std::string("render p.xml -D p-ower=1 -o a.exr") + kQuick, 2, {"-D p-ower=1", "letters, digits"});
  expect(std::string("render -D power=5,5,5 p.xml -D power=1 -o a.exr") + kQuick, 0, {}, {"a.exr"});
  // A name the scene does not use would change nothing: a misspelling, said so with the scene's names.
  expect(std::string("render -D power=5,5,5 p.xml -D powr=1 -o b.exr") + kQuick, 1,
         {"p.xml", "-D powr=1", "no parameter 'powr'", "its parameters: power"});
#endif
  expect(std::string("render cornell-box -D power=1 -o a.exr") + kQuick, 2, {"-D and --animation apply to scene files only"});
}

// Scene validation's messages carry the element's file:line:column in every format that has lines
// (Mitsuba: the top-level element), and the file in those without (OBJ and its MTL).
TEST_F(Robustness, InvalidValuesAreReportedWhereTheyWereWritten) {
#if PATHSPACE_HAS_MITSUBA
  write("neg.xml",
        "<scene version=\"3.0.0\">\n"
        "  <emitter type=\"point\"><point name=\"position\" x=\"0\" y=\"0\" z=\"4\"/><rgb name=\"intensity\" value=\"5, 5, 5\"/></emitter>\n"
        "  <shape type=\"sphere\">\n"
        "    <bsdf type=\"diffuse\"><rgb name=\"reflectance\" value=\"-0.5, 0.5, 0.5\"/></bsdf>\n"
        "  </shape>\n"
        "</scene>\n");
  expect(std::string("render neg.xml -o a.exr") + kQuick, 1, {"neg.xml:3:3: ", "diffuse reflectance", "-0.5"});
#endif
  write("neg.mtl", "newmtl m\nKd -1 0.5 0.5\n");
  write("neg.obj", "mtllib neg.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl m\nf 1 2 3\n");
  expect(std::string("render neg.obj -o a.exr") + kQuick, 1, {"neg.obj: ", "diffuse reflectance", "-1"});
}

TEST_F(Robustness, NonFiniteTexelIsAnInputError) {
  // A 2x1 PFM whose second texel's red is NaN, used as a diffuse reflectance texture.
  std::string pfm = "PF\n2 1\n-1.0\n";
  const float texels[6] = {0.5f, 0.5f, 0.5f, std::nanf(""), 0.f, 0.f};
  pfm.append(reinterpret_cast<const char*>(texels), sizeof texels);
  write("nan.pfm", pfm);
  write("tex.pbrt", std::string(kCamera) + kLight +
                        "Texture \"t\" \"spectrum\" \"imagemap\" \"string filename\" \"nan.pfm\"\n"
                        "Material \"diffuse\" \"texture reflectance\" \"t\"\nShape \"sphere\"\n");
  // The pbrt loader names the statement; every other way into a render meets scene validation's
  // texel check (tests/unit/render_session_test.cpp, SessionValidation).
  expect(std::string("render tex.pbrt -o a.exr") + kQuick, 1, {"tex.pbrt:6:", "NaN or infinite"});
}

TEST_F(Robustness, SceneWithoutLightsWarns) {
  write("dark.pbrt", std::string(kCamera) + "Shape \"sphere\"\n");
  expect(std::string("render dark.pbrt -o a.exr") + kQuick, 0, {"warning: the scene has no light sources"}, {"a.exr"});
}

TEST_F(Robustness, GltfCameraBeyondTheImageLimitIsAnInputError) {
  GltfBuilder b;
  const int pos = b.floats({0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3");
  write("wide.gltf", b.gltf(R"("scenes":[{"nodes":[0,1]}],"nodes":[{"camera":0,"translation":[0,0,5]},{"mesh":0}],)"
                            R"("cameras":[{"type":"perspective","perspective":{"yfov":0.7,"aspectRatio":64.0,"znear":0.1}}],)"
                            R"("meshes":[{"primitives":[{"attributes":{"POSITION":)" +
                            std::to_string(pos) + "}}]}]"));
  expect("render wide.gltf -s 1 -q -o a.exr", 1, {"32768x512", "16384"});
}

// --- outputs that would overwrite each other or an input (file identity, not names) ---

TEST_F(Robustness, OutputsNamingOneFileAreAUsageError) {
  write("a.exr", "old");
  fs::create_symlink("a.exr", dir.file("link.exr"));
  expect(std::string("render -o a.exr --stats ./a.exr") + kQuick, 2, {"-o 'a.exr'", "--stats './a.exr'"});
  expect(std::string("render -o a.exr --variance-out link.exr") + kQuick, 2, {"-o 'a.exr'", "--variance-out 'link.exr'"});
  fs::create_hard_link(dir.file("a.exr"), dir.file("hard.exr"));
  expect(std::string("render -o a.exr b.png --checkpoint hard.exr") + kQuick, 2, {"-o 'a.exr'", "--checkpoint 'hard.exr'"});
}

TEST_F(Robustness, CompareRefusesToOverwriteAnInput) {
  expect(std::string("render -o a.exr b.exr") + kQuick, 0, {}, {"a.exr", "b.exr"});
  expect("compare a.exr b.exr --error-map ./a.exr", 2, {"--error-map './a.exr'", "the input 'a.exr' (image)"});
  fs::create_symlink("b.exr", dir.file("ref.exr"));
  expect("compare a.exr b.exr --error-map ref.exr", 2, {"--error-map 'ref.exr'", "the input 'b.exr' (reference)"});
}

// Every input passes one check (base/regular_file.h): a FIFO is refused without waiting for a
// writer (it used to block in open(), deaf to SIGTERM), a device or a folder is named as such
// instead of being read without end or reported missing.
TEST_F(Robustness, InputsThatAreNotRegularFilesAreNamedAsSuch) {
  for (const char* fifo : {"f.pbrt", "f.exr", "f.ckpt", "f.mtl"}) ASSERT_EQ(::mkfifo(dir.file(fifo).c_str(), 0600), 0) << fifo;
  write("m.obj", "mtllib f.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  expect(std::string("render f.pbrt -o a.exr") + kQuick, 1, {"f.pbrt: is a FIFO (named pipe), not a regular file"});
  expect(std::string("render m.obj -o a.exr") + kQuick, 1, {"f.mtl: is a FIFO"});
  expect(std::string("render --resume f.ckpt -o a.exr") + kQuick, 1, {"f.ckpt: is a FIFO"});
  expect("compare f.exr f.exr", 1, {"f.exr: is a FIFO"});
  ASSERT_EQ(::mkfifo(dir.file("f.bin").c_str(), 0600), 0);
  write("b.gltf", R"({"asset": {"version": "2.0"}, "buffers": [{"uri": "f.bin", "byteLength": 4}]})");
  expect(std::string("render b.gltf -o a.exr") + kQuick, 1, {"f.bin: is a FIFO"});
  expect("info f.pbrt", 1, {"f.pbrt: is a FIFO"});
  expect("compare /dev/zero /dev/zero", 1, {"/dev/zero: is a character device, not a regular file"});
  expect(std::string("render /dev/zero -o a.exr") + kQuick, 1, {"/dev/zero: is a character device"});
  fs::create_directory(dir.file("scenes.pbrt"));
  expect(std::string("render scenes.pbrt -o a.exr") + kQuick, 1, {"scenes.pbrt: is a directory, not a file"});
  expect(std::string("render . -o a.exr") + kQuick, 1, {".: is a directory, not a file"});
}

// A UTF-8 byte-order mark is not an unknown directive; a camera target or up vector without a
// position would be ignored (the scene's camera stays), so it is an error.
TEST_F(Robustness, ByteOrderMarkAndCameraOptionsWithoutAPosition) {
  write("bom.pbrt", std::string("\xEF\xBB\xBF") + kCamera + kLight + "Shape \"sphere\"\n");
  expect(std::string("render bom.pbrt -o a.exr") + kQuick, 0, {}, {"a.exr"});
  expect(std::string("render bom.pbrt -o a.exr --camera-up 0,0,1") + kQuick, 1, {"give --camera-pos too"});
  expect(std::string("render bom.pbrt -o a.exr --camera-target 1,0,0") + kQuick, 1, {"give --camera-pos too"});
  expect(std::string("render bom.pbrt -o a.exr --camera-pos 0,0,5 --camera-up 1,0,0") + kQuick, 0, {}, {"a.exr"});
}

// An output is renamed into place, which would replace a device node by a regular file: refused.
TEST_F(Robustness, DeviceNodesAreNotReplacedByOutputs) {
  expect(std::string("render -o a.exr --stats /dev/null") + kQuick, 1, {"cannot write '/dev/null': it is a character device"});
  EXPECT_TRUE(fs::is_character_file("/dev/null"));
}

// Progress into a closed pipe (`render ... 2>&1 | head -c 1`) no longer kills the render by SIGPIPE:
// it goes quiet, and the render writes its outputs and exits 0.
TEST_F(Robustness, AClosedProgressPipeKeepsTheOutputs) {
  const std::string cmd = "cd '" + dir.path.string() + "' && { '" PATHSPACE_BINARY
                          "' render -r 32x32 -s 64 -o a.exr --stats s.json; echo $? > rc.txt; } 2>&1 | head -c 1 > /dev/null";
  ASSERT_EQ(std::system(cmd.c_str()), 0);
  EXPECT_EQ(read_all(dir.file("rc.txt")), "0\n");
  EXPECT_TRUE(fs::is_regular_file(dir.file("a.exr")));
  EXPECT_TRUE(fs::is_regular_file(dir.file("s.json")));
}

// Replacing an existing output keeps its mode, and a symlink keeps pointing at the file it names,
// which receives the new image (as cp would).
TEST_F(Robustness, OverwritingKeepsModeAndFollowsSymlinks) {
  write("target.exr", "old");
  fs::permissions(dir.file("target.exr"), fs::perms(0640));
  fs::create_symlink("target.exr", dir.file("link.exr"));
  expect(std::string("render -o link.exr") + kQuick, 0, {}, {"target.exr"});
  EXPECT_TRUE(fs::is_symlink(dir.file("link.exr")));
  EXPECT_NE(read_all(dir.file("target.exr")), "old");
  struct stat st {};
  ASSERT_EQ(::stat(dir.file("target.exr").c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 0777, 0640u);
}

// --- numbers that wrapped, were ignored or gave the wrong status ---

TEST_F(Robustness, NumbersAreCheckedWhole) {
  expect("render -o a.exr -s 1 -q -r 4294967297x1", 2, {"--resolution", "4294967297x1"});
  expect("render -o a.exr -r 8x8 -s 1 -q --seed -1", 2, {"--seed '-1'"});
  expect("render -o a.exr -r 8x8 -s 1 -q --seed 18446744073709551616", 2, {"--seed"});
  expect("render -o a.exr -r 8x8 -q --time nan", 2, {"--time 'nan'"});
  expect("render -o a.exr -r 8x8 -s 1 -q --lens-radius nan --focus-distance 1", 2, {"--lens-radius 'nan'"});
  expect("render -o a.exr -r 8x8 -s 1 -q --focus-distance inf --lens-radius 0.1", 2, {"--focus-distance 'inf'"});
  expect("render -o a.exr -r 8x8 -q --spp 1e3", 2, {"--spp '1e3'"});
  expect("render -o a.exr -r 8x8 -s 1 -q --threads 4294967297", 2, {"--threads"});
  expect("study pclt -o st --scenes bs_c --resolution 4294967297x1 --quiet", 2, {"--resolution"});
  expect("study psf -o st --scenes bs_c --time nan --quiet", 2, {"--time 'nan'"});
  expect("study psf -o st --scenes bs_c --seed -1 --quiet", 2, {"--seed '-1'"});
  expect("render -o a.exr -r 8x8 -s 1 -q --max-decompression-ratio -1", 2, {"--max-decompression-ratio '-1'"});
}

TEST_F(Robustness, EmptySceneNameIsAUsageError) { expect(std::string("render '' -o a.exr") + kQuick, 2, {"empty"}); }

// --- messages that blamed the wrong thing or echoed raw bytes ---

TEST_F(Robustness, UnknownCommandNamesTheCommands) {
  expect("rendr cornell-box", 2, {"unknown command 'rendr'", "render", "info", "compare", "study"});
}

TEST_F(Robustness, OutputListSwallowingTheSceneSaysSo) {
  expect(std::string("render -o a.exr cornell-box") + kQuick, 2, {"-o took the scene 'cornell-box'", "--"});
}

TEST_F(Robustness, BinaryBytesAreEscapedInMessages) {
  write("bin.pbrt", std::string("\x01\x1b[31m\xff\xfe junk\n", 12));
  const testing::Run r = expect("render bin.pbrt -o a.exr -q", 1, {"unknown directive '\\x01\\x1b'"});
  for (char c : r.out) EXPECT_TRUE(c == '\n' || uint8_t(c) >= 0x20) << "raw control byte " << int(c) << " in\n" << r.out;
}

TEST_F(Robustness, LoadFailurePrintsTheWarningsSoFar) {
  write("w.pbrt", "Option \"bool disablepixeljitter\" true\n" + std::string(kCamera) + "Shape \"sphere\" \"float radius\" [ 1\n");
  expect("render w.pbrt -o a.exr -q", 1, {"warning: Option is not supported", "error: w.pbrt:"});
}

}  // namespace
}  // namespace pathspace::testing
