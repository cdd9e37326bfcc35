// OBJ/MTL loading through tinyobjloader: triangulation, MTL → material mapping (Kd, Ks/Ns, glass,
// Ke emission), warnings for unsupported statements with file:line, camera framing and options.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "pathspace/base/error.h"
#include "pathspace/io/scene_loader.h"
#include "support/temp_dir.h"

namespace pathspace {
namespace {

namespace fs = std::filesystem;

using pathspace::testing::TempDir;

fs::path write_obj_scene(const fs::path& dir) {
  std::ofstream(dir / "box.mtl") << "newmtl red\nKd 0.5 0.1 0.1\nKs 0.2 0.2 0.2\nNs 50\n"
                                    "newmtl glass\nKd 0 0 0\nNi 1.5\nd 0.2\n"
                                    "newmtl lamp\nKd 0 0 0\nKe 10 9 8\n";
  std::ofstream(dir / "box.obj") << "mtllib box.mtl\n"
                                    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nvn 0 0 1\n"
                                    "usemtl red\nf 1//1 2//1 3//1 4//1\n"  // a quad: two triangles
                                    "usemtl glass\nf 1 2 5\n"
                                    "usemtl lamp\nf 2 3 5\n"
                                    "curv 0 1 1 2\n";
  return dir / "box.obj";
}

TEST(ObjLoader, MaterialsEmissionAndWarnings) {
  const TempDir dir("obj");
  std::vector<std::string> w;
  const Scene s = load_scene(write_obj_scene(dir.path).string(), {}, &w);
  ASSERT_EQ(s.triangles.size(), 4u);
  const Material& red = s.materials[s.triangles[0].material];
  EXPECT_EQ(red.diffuse, Rgb(0.5f, 0.1f, 0.1f));
  EXPECT_EQ(red.glossy, Rgb(0.2f));
  EXPECT_FLOAT_EQ(red.exponent, 50.f);
  const Material& glass = s.materials[s.triangles[2].material];
  EXPECT_FLOAT_EQ(glass.ior, 1.5f);
  ASSERT_EQ(s.lights.size(), 1u);
  EXPECT_EQ(s.lights[0].value, Rgb(10, 9, 8));
  EXPECT_EQ(s.triangles[3].light, 0);
  bool curv = false;
  for (const std::string& m : w) curv |= m.find("box.obj:14:1: warning: OBJ statement 'curv'") != std::string::npos;
  EXPECT_TRUE(curv);
  // vn: the quad's corners carry the shading normal (their own vertices); the others stay flat.
  ASSERT_EQ(s.normals.size(), s.positions.size());
  for (uint32_t v : s.triangles[0].v) EXPECT_EQ(s.normals[v].z, 1.f);
  for (uint32_t v : s.triangles[2].v) EXPECT_EQ(s.normals[v].z, 0.f);
  EXPECT_EQ(s.camera.width, 512);
  // The default camera looks along -z at the centre of the bounds.
  EXPECT_NEAR(s.camera.forward.z, -1.f, 1e-6f);
  EXPECT_NEAR(s.camera.position.x, 0.5f, 1e-6f);
}

TEST(ObjLoader, CameraOptions) {
  SceneLoadOptions o;
  o.width = 40, o.height = 20;
  o.camera_position = Vec3(5, 0.5f, 0.5f);
  o.camera_target = Vec3(0.5f, 0.5f, 0.5f);
  o.fov_degrees = 30.f;
  const TempDir dir("obj");
  const Scene s = load_scene(write_obj_scene(dir.path).string(), o, nullptr);
  EXPECT_EQ(s.camera.position, Vec3(5, 0.5f, 0.5f));
  EXPECT_NEAR(s.camera.forward.x, -1.f, 1e-6f);
  EXPECT_NEAR(s.camera.tan_y, std::tan(15.0 * M_PI / 180.0), 1e-6);
  EXPECT_EQ(s.camera.width, 40);
}

TEST(ObjLoader, Errors) {
  const TempDir temp("obj");
  const fs::path& dir = temp.path;
  std::ofstream(dir / "empty.obj") << "# nothing\n";
  EXPECT_THROW(load_scene((dir / "empty.obj").string(), {}, nullptr), Error);
  EXPECT_THROW(load_scene((dir / "missing.obj").string(), {}, nullptr), Error);
  EXPECT_THROW(load_scene((dir / "scene.xyz").string(), {}, nullptr), Error);
  EXPECT_TRUE(is_scene_file("a/B.OBJ"));
  EXPECT_TRUE(is_scene_file("mesh.ply.gz"));
  EXPECT_FALSE(is_scene_file("cornell-box"));
}

}  // namespace
}  // namespace pathspace
