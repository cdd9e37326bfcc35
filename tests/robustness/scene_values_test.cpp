// Degenerate values in scene files that used to pass without a word (issue 44, part 4): each is an
// error naming the file (and line where the format has lines), and a scene's deep JSON is refused
// before a parser could overflow the stack. Also: no output may replace a file the scene reads, and
// a resumed render notices a changed included file.
#include <gtest/gtest.h>

#include <cstring>
#include <string>

#include "robustness_fixture.h"
#include "support/gltf_test_files.h"

namespace pathspace::testing {
namespace {

using SceneValues = Robustness;

TEST_F(SceneValues, RotationAboutAZeroAxis) {
  write("rot.pbrt", std::string(kCamera) + kLight + "Rotate 30 0 0 0\nShape \"sphere\"\n");
  expect(std::string("render rot.pbrt -o a.exr") + kQuick, 1, {"rot.pbrt:6:1: ", "Rotate needs an axis of nonzero length"});
  write("still.pbrt", std::string(kCamera) + kLight + "Rotate 0 0 0 0\nShape \"sphere\"\n");  // no angle: nothing to guess
  expect(std::string("render still.pbrt -o a.exr") + kQuick, 0, {}, {"a.exr"});
#if PATHSPACE_HAS_MITSUBA
  write("rot.xml",
        "<scene version=\"3.0.0\">\n"
        "  <emitter type=\"point\"><point name=\"position\" x=\"0\" y=\"0\" z=\"4\"/></emitter>\n"
        "  <shape type=\"sphere\"><transform name=\"to_world\"><rotate angle=\"40\"/></transform></shape>\n"
        "</scene>\n");
  expect(std::string("render rot.xml -o b.exr") + kQuick, 1, {"rot.xml:3:", "<rotate> needs an axis of nonzero length"});
#endif
}

std::string triangle_gltf(const std::string& camera, const std::string& material) {
  GltfBuilder b;
  const int pos = b.floats({0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3");
  return b.gltf(R"("scenes":[{"nodes":[0,1]}],"nodes":[{"camera":0,"translation":[0,0,5]},{"mesh":0}],"cameras":[)" + camera +
                R"(],"materials":[)" + material + R"(],"meshes":[{"primitives":[{"material":0,"attributes":{"POSITION":)" +
                std::to_string(pos) + "}}]}]");
}

TEST_F(SceneValues, GltfAspectRatioAndFactorsOutOfRange) {
  const std::string grey = R"({"pbrMetallicRoughness":{"baseColorFactor":[0.5,0.5,0.5,1]}})";
  for (const char* aspect : {"0", "-1.5"}) {
    write("aspect.gltf", triangle_gltf(std::string(R"({"type":"perspective","perspective":{"yfov":0.7,"znear":0.1,"aspectRatio":)") + aspect + "}}", grey));
    expect("render aspect.gltf -s 1 -q -o a.exr", 1, {"aspect.gltf: ", "cameras[0].perspective.aspectRatio must be a number > 0"});
  }
  const std::string camera = R"({"type":"perspective","perspective":{"yfov":0.7,"znear":0.1,"aspectRatio":1.0}})";
  write("neg.gltf", triangle_gltf(camera, R"({"pbrMetallicRoughness":{"baseColorFactor":[-0.5,0.5,0.5,1]}})"));
  expect("render neg.gltf -r 8x8 -s 1 -q -o a.exr", 1, {"neg.gltf: ", "baseColorFactor[0]", "outside [0, 1]"});
  write("rough.gltf", triangle_gltf(camera, R"({"pbrMetallicRoughness":{"roughnessFactor":1.5}})"));
  expect("render rough.gltf -r 8x8 -s 1 -q -o a.exr", 1, {"rough.gltf: ", "roughnessFactor", "outside [0, 1]"});
  write("ok.gltf", triangle_gltf(camera, grey));
  expect("render ok.gltf -r 8x8 -s 1 -q -o a.exr", 0, {}, {"a.exr"});
}

// Deep nesting in extras: tinygltf converts it recursively. Refused by depth, in render and info.
TEST_F(SceneValues, DeeplyNestedGltfJsonIsRefused) {
  const std::string deep = std::string(100000, '[') + std::string(100000, ']');
  write("deep.gltf", R"({"asset":{"version":"2.0","extras":)" + deep + "}}");
  expect("render deep.gltf -r 8x8 -s 1 -q -o a.exr", 1, {"deep.gltf: ", "nests arrays and objects more than 128 deep"});
  expect("info deep.gltf", 1, {"deep.gltf: ", "more than 128 deep"});
}

TEST_F(SceneValues, ObjCoordinatesMustBeComplete) {
  write("flat.obj", "v 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  expect(std::string("render flat.obj -o a.exr") + kQuick, 1, {"flat.obj:1:1: ", "'v' has 2 coordinate(s); it needs 3"});
  write("uv.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 nan\nf 1/1 2/1 3/1\n");
  expect(std::string("render uv.obj -o a.exr") + kQuick, 1, {"uv.obj:4:1: ", "texture coordinate 'nan' is not a finite float"});
  write("n.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 1\nf 1//1 2//1 3//1\n");
  expect(std::string("render n.obj -o a.exr") + kQuick, 1, {"n.obj:4:1: ", "'vn' has 2 coordinate(s)"});
}

TEST_F(SceneValues, MtlNumbersMustBeFinite) {
  write("m.mtl", "newmtl red\nKd 0.5 nan 0.5\n");
  write("m.obj", "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl red\nf 1 2 3\n");
  expect(std::string("render m.obj -o a.exr") + kQuick, 1, {"m.mtl:2:1: ", "'Kd' value 'nan' is not a finite number"});
  write("m.mtl", "newmtl red\nKd 0.5 0.2 0.2\nd -halo 1\nNs 10\n");
  expect(std::string("render m.obj -o a.exr") + kQuick, 0, {}, {"a.exr"});
}

TEST_F(SceneValues, PlyTextureCoordinatesMustBeFinite) {
  std::string ply =
      "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
      "property float u\nproperty float v\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
  const float nan = std::nanf("");
  const float v[15] = {0, 0, 0, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0, nan, 1};
  ply.append(reinterpret_cast<const char*>(v), sizeof v);
  ply += '\3';
  const int f[3] = {0, 1, 2};
  ply.append(reinterpret_cast<const char*>(f), sizeof f);
  write("uv.ply", ply);
  expect(std::string("render uv.ply -o a.exr") + kQuick, 1, {"uv.ply", "vertex texture coordinate is NaN or infinite"});
}

// Every file the scene reads is an input: an output may not replace an Include, and a render
// resumed after an included file changed is refused (the checkpoint's key covers every file).
TEST_F(SceneValues, FilesTheSceneReadsAreInputs) {
  write("part.pbrt", "Shape \"sphere\"\n");
  write("main.pbrt", std::string(kCamera) + kLight + "Include \"part.pbrt\"\n");
  expect(std::string("render main.pbrt -o a.exr --stats part.pbrt") + kQuick, 2,
         {"--stats 'part.pbrt' would overwrite the input 'part.pbrt' (read by the scene)"});
  expect("render main.pbrt -r 8x8 -s 1 -q -o a.exr --checkpoint ck", 0, {}, {"a.exr", "ck"});
  write("part.pbrt", "Shape \"sphere\" \"float radius\" 0.5\n");
  expect("render main.pbrt -r 8x8 -s 2 -q -o a.exr --resume ck", 2, {"--resume: the checkpoint was made for the scene", "every file it reads"},
         {"a.exr", "ck", "part.pbrt"});
}

}  // namespace
}  // namespace pathspace::testing
