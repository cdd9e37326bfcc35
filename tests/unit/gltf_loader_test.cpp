// glTF loader: geometry, node transforms, camera, material mappings, KHR_lights_punctual, textures,
// .gltf vs .glb, malformed input, and a render of a glTF box against the same box as OBJ.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iterator>

#include "pathspace/base/error.h"
#include "pathspace/io/image_io.h"
#include "pathspace/io/scene_loader.h"
#include "support/gltf_test_files.h"
#include "support/integrator_comparison.h"
#include "support/temp_dir.h"

namespace pathspace {
namespace {

using testing::GltfBuilder;

constexpr float kPi = 3.14159265358979f;

struct Loaded {
  Scene scene;
  std::vector<std::string> warnings;
  bool warned(const std::string& part) const {
    for (const std::string& w : warnings)
      if (w.find(part) != std::string::npos) return true;
    return false;
  }
};

Loaded load_text(const testing::TempDir& dir, const std::string& name, const std::string& bytes, const SceneLoadOptions& o = {}) {
  testing::write_bytes(dir.file(name), bytes);
  Loaded l;
  l.scene = load_scene(dir.file(name), o, &l.warnings);
  return l;
}

// A unit triangle in the xy plane (normal +z) and a quad of two triangles, indexed.
struct Shapes {
  GltfBuilder b;
  int tri_pos, quad_pos, quad_idx;
  Shapes() {
    tri_pos = b.floats({0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3");
    quad_pos = b.floats({-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0}, "VEC3");
    quad_idx = b.indices({0, 1, 2, 2, 3, 0});
  }
  std::string triangle_mesh(const std::string& material = "") const {
    return "{\"primitives\":[{\"attributes\":{\"POSITION\":" + std::to_string(tri_pos) + "}" + material + "}]}";
  }
  std::string quad_mesh(const std::string& material = "") const {
    return "{\"primitives\":[{\"attributes\":{\"POSITION\":" + std::to_string(quad_pos) + "},\"indices\":" + std::to_string(quad_idx) +
           material + "}]}";
  }
};

// A light so that loading does not add the white environment.
const char* const kLightExt = R"("extensionsUsed":["KHR_lights_punctual"],"extensions":{"KHR_lights_punctual":{"lights":[{"type":"point","intensity":2}]}})";

Vec3 vertex(const Scene& s, size_t tri, int k) { return s.positions[s.triangles[tri].v[k]]; }
void expect_near(const Vec3& a, const Vec3& b, float eps = 1e-5f) {
  EXPECT_NEAR(a.x, b.x, eps);
  EXPECT_NEAR(a.y, b.y, eps);
  EXPECT_NEAR(a.z, b.z, eps);
}

TEST(GltfLoader, IndexedAndNonIndexedTriangles) {
  testing::TempDir dir("gltf");
  Shapes s;
  const Loaded l = load_text(dir, "a.gltf", s.b.gltf(R"("scene":0,"scenes":[{"nodes":[0,1]}],"nodes":[{"mesh":0},{"mesh":1}],"meshes":[)" +
                                                     s.triangle_mesh() + "," + s.quad_mesh() + "]"));
  ASSERT_EQ(l.scene.triangles.size(), 3u);
  expect_near(vertex(l.scene, 0, 1), Vec3(1, 0, 0));
  expect_near(vertex(l.scene, 1, 2), Vec3(1, 1, 0));
  expect_near(vertex(l.scene, 2, 1), Vec3(-1, 1, 0));
  EXPECT_TRUE(l.warned("no emitters")) << "white environment added";
  EXPECT_EQ(l.scene.lights.size(), 1u);
}

TEST(GltfLoader, NodeTransformsComposeParentTimesLocal) {
  testing::TempDir dir("gltf");
  Shapes s;
  // Parent: translate (10,0,0), rotate 90 degrees about +y, scale 2. Child: matrix translating (0,0,1).
  const float h = std::sqrt(0.5f);
  const std::string nodes = R"("nodes":[{"translation":[10,0,0],"rotation":[0,)" + std::to_string(h) + ",0," + std::to_string(h) +
                            R"(],"scale":[2,2,2],"children":[1]},{"matrix":[1,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,1,1],"mesh":0}])";
  const Loaded l = load_text(dir, "t.gltf", s.b.gltf(R"("scenes":[{"nodes":[0]}],)" + nodes + ",\"meshes\":[" + s.triangle_mesh() + "]"));
  ASSERT_EQ(l.scene.triangles.size(), 1u);
  // Ry(90): x -> -z, z -> x. Child vertex (0,0,0) -> (0,0,1) -> scale (0,0,2) -> rotate (2,0,0) -> (12,0,0).
  expect_near(vertex(l.scene, 0, 0), Vec3(12, 0, 0));
  // (1,0,0) -> (1,0,1) -> (2,0,2) -> (2,0,-2) -> (12,0,-2); (0,1,0) -> (0,1,1) -> (0,2,2) -> (2,2,0) -> (12,2,0).
  expect_near(vertex(l.scene, 0, 1), Vec3(12, 0, -2));
  expect_near(vertex(l.scene, 0, 2), Vec3(12, 2, 0));
}

TEST(GltfLoader, MirroringTransformKeepsFrontFaces) {
  testing::TempDir dir("gltf");
  Shapes s;
  const Loaded l = load_text(dir, "m.gltf", s.b.gltf(R"("scenes":[{"nodes":[0]}],"nodes":[{"scale":[-1,1,1],"mesh":0}],"meshes":[)" +
                                                     s.triangle_mesh() + "]"));
  const Vec3 n = cross(vertex(l.scene, 0, 1) - vertex(l.scene, 0, 0), vertex(l.scene, 0, 2) - vertex(l.scene, 0, 0));
  EXPECT_GT(n.z, 0.f) << "the +z front face must stay +z after mirroring x";
}

TEST(GltfLoader, CameraLooksDownMinusZWithYUp) {
  testing::TempDir dir("gltf");
  Shapes s;
  // Camera at (0,0,5), default orientation; a triangle to the right (+x) and above (+y) of the axis.
  const std::string rest = R"("scenes":[{"nodes":[0,1]}],"nodes":[{"camera":0,"translation":[0,0,5]},{"mesh":0,"translation":[0.5,0.5,0]}],)"
                           R"("cameras":[{"type":"perspective","perspective":{"yfov":0.7,"aspectRatio":2.0,"znear":0.1}}],"meshes":[)" +
                           s.triangle_mesh() + "]";
  const Loaded l = load_text(dir, "c.gltf", s.b.gltf(rest));
  const PerspectiveCamera& c = l.scene.camera;
  EXPECT_EQ(c.width, 1024);
  EXPECT_EQ(c.height, 512);
  expect_near(c.position, Vec3(0, 0, 5));
  expect_near(c.forward, Vec3(0, 0, -1));
  expect_near(c.up, Vec3(0, 1, 0));
  EXPECT_NEAR(c.tan_y, std::tan(0.35f), 1e-6f);
  EXPECT_NEAR(c.tan_x, 2.f * std::tan(0.35f), 1e-6f);
  float rx = 0, ry = 0;
  const Vec3 centroid = (vertex(l.scene, 0, 0) + vertex(l.scene, 0, 1) + vertex(l.scene, 0, 2)) / 3.f;
  ASSERT_TRUE(c.raster_from_direction(normalize(centroid - c.position), &rx, &ry));
  EXPECT_GT(rx, 512.f) << "object at +x appears right of the centre";
  EXPECT_LT(ry, 256.f) << "object at +y appears above the centre";

  // -r overrides the resolution; yfov stays the vertical field of view.
  SceneLoadOptions o;
  o.width = 100;
  o.height = 200;
  const Loaded r = load_text(dir, "c2.gltf", s.b.gltf(rest), o);
  EXPECT_NEAR(r.scene.camera.tan_y, std::tan(0.35f), 1e-6f);
  EXPECT_NEAR(r.scene.camera.tan_x, 0.5f * std::tan(0.35f), 1e-6f);
}

TEST(GltfLoader, RotatedCameraAndCameraOptions) {
  testing::TempDir dir("gltf");
  Shapes s;
  // Rotated 90 degrees about +y: looks down -x.
  const float h = std::sqrt(0.5f);
  const std::string rest = R"("scenes":[{"nodes":[0,1]}],"nodes":[{"camera":0,"rotation":[0,)" + std::to_string(h) + ",0," + std::to_string(h) +
                           R"(]},{"mesh":0}],"cameras":[{"type":"perspective","perspective":{"yfov":0.5,"znear":0.1}}],"meshes":[)" +
                           s.triangle_mesh() + "]";
  const Loaded l = load_text(dir, "r.gltf", s.b.gltf(rest));
  expect_near(l.scene.camera.forward, Vec3(-1, 0, 0));
  expect_near(l.scene.camera.right, Vec3(0, 0, -1));
  EXPECT_EQ(l.scene.camera.width, 512);
  SceneLoadOptions o;
  o.camera_position = Vec3(0, 0, 9);
  o.camera_target = Vec3(0, 0, 0);
  const Loaded m = load_text(dir, "r2.gltf", s.b.gltf(rest), o);
  expect_near(m.scene.camera.position, Vec3(0, 0, 9));
  expect_near(m.scene.camera.forward, Vec3(0, 0, -1));
}

std::string material_scene(const Shapes& s, const std::string& materials, int count, const std::string& extra = "") {
  std::string nodes, meshes;
  for (int i = 0; i < count; ++i) {
    nodes += std::string(i ? "," : "") + "{\"mesh\":" + std::to_string(i) + "}";
    meshes += std::string(i ? "," : "") + s.quad_mesh(",\"material\":" + std::to_string(i));
  }
  std::string roots;
  for (int i = 0; i < count; ++i) roots += std::string(i ? "," : "") + std::to_string(i);
  return s.b.gltf("\"scenes\":[{\"nodes\":[" + roots + "]}],\"nodes\":[" + nodes + "],\"meshes\":[" + meshes + "],\"materials\":[" + materials +
                  "]" + extra);
}

TEST(GltfLoader, MaterialMappings) {
  testing::TempDir dir("gltf");
  Shapes s;
  const std::string materials =
      // 0: dielectric base, rough: Lambert * (1 - 0.04) + Phong coat
      R"({"pbrMetallicRoughness":{"baseColorFactor":[0.5,0.25,1,1],"metallicFactor":0,"roughnessFactor":0.5},"doubleSided":true,"occlusionTexture":{"index":0}},)"
      // 1: metal, roughness 0.5 -> alpha 0.25, F0 = baseColor
      R"({"pbrMetallicRoughness":{"baseColorFactor":[0.9,0.5,0.2,1],"metallicFactor":1,"roughnessFactor":0.5}},)"
      // 2: smooth transmission with ior 1.33
      R"({"pbrMetallicRoughness":{"baseColorFactor":[1,1,0.8,1],"metallicFactor":0,"roughnessFactor":0},"extensions":{"KHR_materials_transmission":{"transmissionFactor":1},"KHR_materials_ior":{"ior":1.33}}},)"
      // 3: rough transmission
      R"({"pbrMetallicRoughness":{"metallicFactor":0,"roughnessFactor":0.3},"extensions":{"KHR_materials_transmission":{"transmissionFactor":1}}},)"
      // 4: emissive with strength, smooth dielectric base (mirror coat)
      R"({"pbrMetallicRoughness":{"baseColorFactor":[0,0,0,1],"metallicFactor":0,"roughnessFactor":0},"emissiveFactor":[1,0.5,0.25],"extensions":{"KHR_materials_emissive_strength":{"emissiveStrength":4},"KHR_materials_clearcoat":{}}})";
  const std::string extra = R"(,"textures":[{"source":0}],"images":[{"uri":"missing.png"}])";
  const Loaded l = load_text(dir, "mat.gltf", material_scene(s, materials, 5, extra));
  const Scene& sc = l.scene;
  ASSERT_EQ(sc.triangles.size(), 10u);
  auto mat = [&](int quad) { return sc.materials[sc.triangles[size_t(2 * quad)].material]; };

  const Material m0 = mat(0);
  EXPECT_EQ(m0.type, MaterialType::standard);
  EXPECT_TRUE(m0.two_sided);
  EXPECT_NEAR(m0.diffuse.r, 0.5f * 0.96f, 1e-6f);
  EXPECT_NEAR(m0.diffuse.b, 0.96f, 1e-6f);
  EXPECT_NEAR(m0.glossy.g, 0.04f, 1e-6f);
  EXPECT_NEAR(m0.exponent, 2.f / (0.25f * 0.25f) - 2.f, 1e-3f);
  EXPECT_TRUE(l.warned("materials[0].occlusionTexture ignored"));

  const Material m1 = mat(1);
  EXPECT_EQ(m1.type, MaterialType::rough_conductor);
  EXPECT_NEAR(m1.alpha, 0.25f, 1e-6f);
  for (int i = 0; i < 3; ++i) {  // eta = 1: F0 = k^2 / (4 + k^2) must give back baseColor
    const float k = m1.k[i];
    EXPECT_NEAR(m1.eta[i], 1.f, 1e-6f);
    EXPECT_NEAR(k * k / (4.f + k * k), (Rgb(0.9f, 0.5f, 0.2f))[i], 1e-5f);
  }
  EXPECT_FALSE(m1.two_sided);

  const Material m2 = mat(2);
  EXPECT_EQ(m2.type, MaterialType::standard);
  EXPECT_NEAR(m2.ior, 1.33f, 1e-6f);
  EXPECT_NEAR(m2.specular.b, 0.8f, 1e-6f);
  EXPECT_TRUE(is_black(m2.diffuse));

  const Material m3 = mat(3);
  EXPECT_EQ(m3.type, MaterialType::rough_dielectric);
  EXPECT_NEAR(m3.alpha, 0.09f, 1e-6f);
  EXPECT_NEAR(m3.ior, 1.5f, 1e-6f);

  const Material m4 = mat(4);
  EXPECT_NEAR(m4.specular.r, 0.04f, 1e-6f);
  // The emissive quad's two triangles, and (no light source in the file) the viewers' white environment.
  ASSERT_EQ(sc.lights.size(), 3u);
  EXPECT_EQ(sc.lights.back().type, LightType::environment);
  EXPECT_TRUE(l.warned("no light sources in the file (only 2 emissive triangles)"));
  for (const Light& li : std::vector<Light>(sc.lights.begin(), sc.lights.end() - 1)) {
    EXPECT_EQ(li.type, LightType::area_triangle);
    EXPECT_NEAR(li.value.r, 4.f, 1e-6f);
    EXPECT_NEAR(li.value.g, 2.f, 1e-6f);
    EXPECT_NEAR(li.value.b, 1.f, 1e-6f);
    EXPECT_FALSE(li.two_sided);
  }
  EXPECT_EQ(sc.triangles[8].light, 0);
  EXPECT_TRUE(l.warned("materials[4].extensions.KHR_materials_clearcoat ignored"));
  EXPECT_FALSE(l.warned("no emitters"));
}

TEST(GltfLoader, DefaultMaterialIsARoughWhiteMetal) {
  testing::TempDir dir("gltf");
  Shapes s;
  const Loaded l = load_text(dir, "d.gltf", s.b.gltf(R"("scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],"meshes":[)" + s.triangle_mesh() + "]"));
  const Material& m = l.scene.materials[l.scene.triangles[0].material];
  EXPECT_EQ(m.type, MaterialType::rough_conductor);
  EXPECT_NEAR(m.alpha, 1.f, 1e-6f);
}

TEST(GltfLoader, PunctualLights) {
  testing::TempDir dir("gltf");
  Shapes s;
  const float h = std::sqrt(0.5f);
  const std::string rest =
      R"("extensionsUsed":["KHR_lights_punctual"],"extensions":{"KHR_lights_punctual":{"lights":[)"
      R"({"type":"point","color":[1,0.5,0.25],"intensity":8,"range":3},{"type":"spot","intensity":3,"spot":{"outerConeAngle":0.5}},{"type":"directional","intensity":2}]}},)"
      R"("scenes":[{"nodes":[0,1,2,3]}],"nodes":[{"mesh":0},)"
      R"({"translation":[1,2,3],"extensions":{"KHR_lights_punctual":{"light":0}}},)"
      R"({"translation":[0,4,0],"extensions":{"KHR_lights_punctual":{"light":1}}},)"
      R"({"rotation":[)" +
      std::to_string(-h) + ",0,0," + std::to_string(h) + R"(],"extensions":{"KHR_lights_punctual":{"light":2}}}],"meshes":[)" + s.triangle_mesh() + "]";
  const Loaded l = load_text(dir, "l.gltf", s.b.gltf(rest));
  ASSERT_EQ(l.scene.lights.size(), 3u);
  const Light& p = l.scene.lights[0];
  EXPECT_EQ(p.type, LightType::point);
  expect_near(p.position, Vec3(1, 2, 3));
  EXPECT_NEAR(p.value.r, 8.f, 1e-6f);
  EXPECT_NEAR(p.value.b, 2.f, 1e-6f);
  EXPECT_TRUE(l.warned("lights[0].range ignored"));
  const Light& spot = l.scene.lights[1];
  EXPECT_EQ(spot.type, LightType::spot);
  EXPECT_NEAR(spot.value.g, 3.f, 1e-6f);
  expect_near(spot.direction, Vec3(0, 0, -1));  // the node's -z
  EXPECT_NEAR(spot.cos_total, std::cos(0.5f), 1e-6f);
  EXPECT_NEAR(spot.cos_falloff, 1.f, 1e-6f);  // innerConeAngle defaults to 0
  EXPECT_TRUE(l.warned("spot falloff approximated"));
  const Light& d = l.scene.lights[2];
  EXPECT_EQ(d.type, LightType::directional);
  // Rotation -90 degrees about x turns -z into -y: the light shines straight down.
  expect_near(d.direction, Vec3(0, -1, 0));
  EXPECT_NEAR(d.value.r, 2.f, 1e-6f);
}

// A 2x2 image: top row red, green; bottom row blue, white (8-bit PNG, sRGB).
std::string png_2x2(const testing::TempDir& dir) {
  Image img(2, 2);
  img.at(0, 0) = Rgb(1, 0, 0);
  img.at(1, 0) = Rgb(0, 1, 0);
  img.at(0, 1) = Rgb(0, 0, 1);
  img.at(1, 1) = Rgb(1, 1, 1);
  write_image(dir.file("tex.png"), img);
  std::ifstream in(dir.file("tex.png"), std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

std::string textured_scene(GltfBuilder& b, const std::string& images) {
  const int pos = b.floats({0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3");
  const int uv = b.floats({0, 0, 1, 0, 0, 1}, "VEC2");
  const int nrm = b.floats({0, 0, 2, 0, 0, 1, 0, 0, 1}, "VEC3");
  return "\"scenes\":[{\"nodes\":[0]}],\"nodes\":[{\"mesh\":0,\"scale\":[1,1,3]}],\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":" +
         std::to_string(pos) + ",\"TEXCOORD_0\":" + std::to_string(uv) + ",\"NORMAL\":" + std::to_string(nrm) +
         "},\"material\":0}]}],\"materials\":[{\"pbrMetallicRoughness\":{\"metallicFactor\":0,\"baseColorFactor\":[0.5,1,1,1],"
         "\"baseColorTexture\":{\"index\":0}}}],\"textures\":[{\"source\":0}],\"images\":[" +
         images + "]";
}

void expect_texture(const Loaded& l) {
  const Scene& sc = l.scene;
  const Material& m = sc.materials[sc.triangles[0].material];
  ASSERT_GE(m.diffuse_texture, 0);
  const ImageTexture& t = sc.textures[size_t(m.diffuse_texture)];
  ASSERT_EQ(t.width, 2);
  EXPECT_NEAR(t.texel(0).r, 1.f, 1e-3f);  // sRGB-decoded red
  EXPECT_NEAR(t.texel(3).b, 1.f, 1e-3f);
  EXPECT_NEAR(m.diffuse.r, 0.5f * 0.96f, 1e-6f);  // the factor multiplies the texture
  // glTF uv (0,0) is the image's top-left corner; ours is the bottom-left: v is flipped.
  ASSERT_EQ(sc.uvs.size(), sc.positions.size());
  EXPECT_NEAR(sc.uvs[sc.triangles[0].v[0]].y, 1.f, 1e-6f);
  EXPECT_NEAR(sc.uvs[sc.triangles[0].v[2]].y, 0.f, 1e-6f);
  EXPECT_NEAR(sc.uvs[sc.triangles[0].v[1]].x, 1.f, 1e-6f);
  // Normals: normalised, transformed with the inverse transpose (scale z by 3 keeps +z).
  ASSERT_EQ(sc.normals.size(), sc.positions.size());
  expect_near(sc.normals[sc.triangles[0].v[0]], Vec3(0, 0, 1));
}

TEST(GltfLoader, ExternalAndEmbeddedTextures) {
  testing::TempDir dir("gltf");
  const std::string png = png_2x2(dir);
  {
    GltfBuilder b;
    const std::string rest = textured_scene(b, R"({"uri":"tex.png"})") + "," + kLightExt;
    expect_texture(load_text(dir, "ext.gltf", b.gltf(rest)));
  }
  {
    GltfBuilder b;
    const std::string rest = textured_scene(b, "{\"uri\":\"data:image/png;base64," + testing::base64(png) + "\"}") + "," + kLightExt;
    expect_texture(load_text(dir, "uri.gltf", b.gltf(rest)));
  }
  {
    GltfBuilder b;
    const int view = b.view(png);
    const std::string rest = textured_scene(b, "{\"bufferView\":" + std::to_string(view) + ",\"mimeType\":\"image/png\"}") + "," + kLightExt;
    expect_texture(load_text(dir, "bin.glb", b.glb(rest)));
  }
  {  // a missing image: warning, constant factor
    GltfBuilder b;
    const Loaded l = load_text(dir, "miss.gltf", b.gltf(textured_scene(b, R"({"uri":"nope.png"})")));
    EXPECT_EQ(l.scene.materials[l.scene.triangles[0].material].diffuse_texture, -1);
    EXPECT_TRUE(l.warned("images[0] not used"));
  }
}

// An emissiveTexture is the emitting triangles' emission map (the factor times the texture at uv),
// and a sampler's CLAMP_TO_EDGE and NEAREST reach the texture.
TEST(GltfLoader, EmissiveTextureIsTheLightsMap) {
  testing::TempDir dir("gltf");
  const std::string png = png_2x2(dir);
  GltfBuilder b;
  std::string rest = textured_scene(b, R"({"uri":"tex.png"})");
  const std::string material = R"("materials":[{"pbrMetallicRoughness":{"metallicFactor":0,"baseColorFactor":[0.5,1,1,1],"baseColorTexture":{"index":0}}}])";
  rest.replace(rest.find(material), material.size(),
               R"("materials":[{"emissiveFactor":[1,0.5,1],"emissiveTexture":{"index":0},"pbrMetallicRoughness":{"metallicFactor":0}}],)"
               R"("samplers":[{"wrapS":33071,"wrapT":33071,"magFilter":9728}])");
  const std::string textures = R"("textures":[{"source":0}])";
  rest.replace(rest.find(textures), textures.size(), R"("textures":[{"source":0,"sampler":0}])");
  const Loaded l = load_text(dir, "glow.gltf", b.gltf(rest));
  const Scene& sc = l.scene;
  ASSERT_EQ(sc.lights.size(), 2u);  // the triangle, and the environment of a file without light sources
  const Light& glow = sc.lights[0];
  EXPECT_EQ(glow.type, LightType::area_triangle);
  ASSERT_GE(glow.texture, 0);
  EXPECT_EQ(glow.value, Rgb(1.f, 0.5f, 1.f));
  const ImageTexture& t = sc.textures[size_t(glow.texture)];
  EXPECT_NEAR(t.texel(0).r, 1.f, 1e-3f);
  EXPECT_EQ(t.wrap, TextureWrap::clamp);
  EXPECT_TRUE(t.nearest);
  EXPECT_FALSE(l.warned("emissiveTexture"));
}

TEST(GltfLoader, GlbMatchesGltf) {
  testing::TempDir dir("gltf");
  Shapes s;
  const std::string rest = R"("scenes":[{"nodes":[0]}],"nodes":[{"mesh":0,"translation":[0,1,0]}],"meshes":[)" + s.quad_mesh() + "]," + kLightExt;
  const Loaded a = load_text(dir, "s.gltf", s.b.gltf(rest));
  const Loaded b = load_text(dir, "s.glb", s.b.glb(rest));
  ASSERT_EQ(a.scene.triangles.size(), b.scene.triangles.size());
  for (size_t t = 0; t < a.scene.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) expect_near(vertex(a.scene, t, k), vertex(b.scene, t, k), 0.f);
}

TEST(GltfLoader, UnsupportedFeaturesWarn) {
  testing::TempDir dir("gltf");
  GltfBuilder b;
  const int pos = b.floats({0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3");
  const int col = b.floats({1, 0, 0, 0, 1, 0, 0, 0, 1}, "VEC3");
  const std::string rest = "\"scenes\":[{\"nodes\":[0]},{\"nodes\":[]}],\"nodes\":[{\"mesh\":0}],\"meshes\":[{\"primitives\":[{\"attributes\":"
                           "{\"POSITION\":" + std::to_string(pos) + ",\"COLOR_0\":" + std::to_string(col) +
                           "}},{\"attributes\":{\"POSITION\":" + std::to_string(pos) + "},\"mode\":1}]}],\"extensionsUsed\":[\"KHR_materials_sheen\"]";
  const Loaded l = load_text(dir, "u.gltf", b.gltf(rest));
  EXPECT_EQ(l.scene.triangles.size(), 1u);
  EXPECT_TRUE(l.warned("meshes[0].primitives[0].attributes.COLOR_0 ignored"));
  EXPECT_TRUE(l.warned("meshes[0].primitives[1].mode 1"));
  EXPECT_TRUE(l.warned("extensionsUsed: KHR_materials_sheen"));
  EXPECT_TRUE(l.warned("only scenes[0] of 2"));
}

// Loading must give a scene or an Error naming the file; returns the error text ("" when loaded).
std::string load_error(const testing::TempDir& dir, const std::string& name, const std::string& bytes) {
  testing::write_bytes(dir.file(name), bytes);
  std::vector<std::string> warnings;
  try {
    load_scene(dir.file(name), {}, &warnings);
  } catch (const pathspace::Error& e) {
    EXPECT_EQ(e.location().file, dir.file(name)) << e.what();
    return e.what();
  }
  return "";
}

TEST(GltfLoader, MalformedFilesAreErrorsNamingTheFile) {
  testing::TempDir dir("gltf");
  Shapes s;
  const std::string good = s.b.gltf(R"("scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],"meshes":[)" + s.quad_mesh() + "]");
  EXPECT_EQ(load_error(dir, "ok.gltf", good), "");
  EXPECT_NE(load_error(dir, "garbage.gltf", "not json at all {{{"), "");
  EXPECT_NE(load_error(dir, "empty.glb", ""), "");
  EXPECT_NE(load_error(dir, "cycle.gltf", s.b.gltf(R"("scenes":[{"nodes":[0]}],"nodes":[{"children":[1]},{"children":[0],"mesh":0}],"meshes":[)" +
                                                    s.quad_mesh() + "]")),
            "");
  EXPECT_NE(load_error(dir, "badmesh.gltf", s.b.gltf(R"("scenes":[{"nodes":[0]}],"nodes":[{"mesh":5}],"meshes":[)" + s.quad_mesh() + "]")), "");
  // An index naming a vertex that does not exist, and an accessor reaching past its bufferView.
  GltfBuilder b;
  const int pos = b.floats({0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3");
  const int idx = b.indices({0, 1, 7});
  const std::string bad_index = load_error(
      dir, "idx.gltf",
      b.gltf("\"scenes\":[{\"nodes\":[0]}],\"nodes\":[{\"mesh\":0}],\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":" + std::to_string(pos) +
             "},\"indices\":" + std::to_string(idx) + "}]}]"));
  EXPECT_NE(bad_index.find("index 7"), std::string::npos) << bad_index;
  std::string overrun = good;
  overrun.replace(overrun.find("\"count\":4"), 9, "\"count\":400");  // the quad's POSITION
  EXPECT_NE(load_error(dir, "overrun.gltf", overrun).find("does not fit"), std::string::npos);
  // Truncations of a valid .gltf and .glb at many lengths, and byte flips: never a crash.
  const std::string glb = s.b.glb(R"("scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],"meshes":[)" + s.quad_mesh() + "]");
  for (size_t n = 0; n < good.size(); n += 5) load_error(dir, "cut.gltf", good.substr(0, n));
  for (size_t n = 0; n < glb.size(); n += 3) load_error(dir, "cut.glb", glb.substr(0, n));
  for (size_t i = 0; i < glb.size(); i += 2) {
    std::string flipped = glb;
    flipped[i] = char(flipped[i] ^ 0x5a);
    load_error(dir, "flip.glb", flipped);
  }
}

// The same open box (grey walls) with an emissive quad under its ceiling, as OBJ/MTL and as glTF:
// Kd 0.48 + Ks 0.04 with Ns 30 is the glTF mapping of baseColor 0.5, roughness 0.5 (F0 = 0.04,
// exponent 2/0.25^2 - 2 = 30); the emitter's ior 1 makes its glTF material black like the OBJ's.
TEST(GltfLoader, RendersLikeTheSameObjScene) {
  testing::TempDir dir("gltf");
  const std::vector<float> walls = {-1, -1, 1, 1, -1, 1, 1, -1, -1, -1, -1, -1,  // floor (normal +y)
                                    -1, 1, -1, 1, 1, -1, 1, 1, 1, -1, 1, 1,      // ceiling (normal -y)
                                    -1, -1, -1, 1, -1, -1, 1, 1, -1, -1, 1, -1,  // back (normal +z)
                                    -1, -1, 1, -1, -1, -1, -1, 1, -1, -1, 1, 1,  // left (normal +x)
                                    1, -1, -1, 1, -1, 1, 1, 1, 1, 1, 1, -1};     // right (normal -x)
  const std::vector<float> light = {-0.3f, 0.99f, -0.3f, 0.3f, 0.99f, -0.3f, 0.3f, 0.99f, 0.3f, -0.3f, 0.99f, 0.3f};  // normal -y
  std::vector<uint32_t> quads;
  for (uint32_t q = 0; q < 5; ++q)
    for (uint32_t k : {0u, 1u, 2u, 2u, 3u, 0u}) quads.push_back(4 * q + k);
  const std::vector<uint32_t> one_quad(quads.begin(), quads.begin() + 6);

  std::string obj = "mtllib box.mtl\n";
  for (const std::vector<float>* v : {&walls, &light})
    for (size_t i = 0; i < v->size(); i += 3) obj += "v " + std::to_string((*v)[i]) + " " + std::to_string((*v)[i + 1]) + " " + std::to_string((*v)[i + 2]) + "\n";
  obj += "usemtl wall\n";
  for (size_t i = 0; i < quads.size(); i += 3) obj += "f " + std::to_string(quads[i] + 1) + " " + std::to_string(quads[i + 1] + 1) + " " + std::to_string(quads[i + 2] + 1) + "\n";
  obj += "usemtl lamp\nf 21 22 23\nf 23 24 21\n";
  testing::write_bytes(dir.file("box.obj"), obj);
  testing::write_bytes(dir.file("box.mtl"), "newmtl wall\nKd 0.48 0.48 0.48\nKs 0.04 0.04 0.04\nNs 30\nnewmtl lamp\nKd 0 0 0\nKe 8 8 8\n");

  GltfBuilder b;
  const int wp = b.floats(walls, "VEC3"), wi = b.indices(quads), lp = b.floats(light, "VEC3"), li = b.indices(one_quad);
  const std::string gltf =
      b.gltf("\"scenes\":[{\"nodes\":[0,1]}],\"nodes\":[{\"mesh\":0},{\"camera\":0,\"translation\":[0,0,3]}],"
             "\"cameras\":[{\"type\":\"perspective\",\"perspective\":{\"yfov\":" + std::to_string(45.0 * 3.14159265358979 / 180.0) +
             ",\"aspectRatio\":1,\"znear\":0.01}}],\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":" + std::to_string(wp) +
             "},\"indices\":" + std::to_string(wi) + ",\"material\":0},{\"attributes\":{\"POSITION\":" + std::to_string(lp) +
             "},\"indices\":" + std::to_string(li) + ",\"material\":1}]}],\"materials\":["
             "{\"doubleSided\":true,\"pbrMetallicRoughness\":{\"baseColorFactor\":[0.5,0.5,0.5,1],\"metallicFactor\":0,\"roughnessFactor\":0.5}},"
             "{\"emissiveFactor\":[1,1,1],\"pbrMetallicRoughness\":{\"baseColorFactor\":[0,0,0,1],\"metallicFactor\":0},"
             "\"extensions\":{\"KHR_materials_emissive_strength\":{\"emissiveStrength\":8},\"KHR_materials_ior\":{\"ior\":1}}}]");
  testing::write_bytes(dir.file("box.gltf"), gltf);

  SceneLoadOptions o;
  o.width = o.height = 24;
  std::vector<std::string> warnings;
  const Scene g = load_scene(dir.file("box.gltf"), o, &warnings);
  o.camera_position = Vec3(0, 0, 3);
  o.camera_target = Vec3(0, 0, 0);
  o.fov_degrees = 45.f;
  Scene m = load_scene(dir.file("box.obj"), o, &warnings);
  // A glTF file without light sources is also lit by the viewers' white environment: the OBJ too.
  m.add_environment_light(Rgb(1.f));
  m.finalize();
  ASSERT_EQ(g.triangles.size(), m.triangles.size());
  ASSERT_EQ(g.lights.size(), m.lights.size());
  expect_near(g.camera.forward, m.camera.forward);
  EXPECT_NEAR(g.camera.tan_x, m.camera.tan_x, 1e-6f);

  // Independent seeds: the z-test assumes independent estimates.
  const testing::Rendered rg = testing::render_integrator(g, make_render_config("pt", PtSettings{}, testing::test_seed(11)), 128);
  const testing::Rendered rm = testing::render_integrator(m, make_render_config("pt", PtSettings{}, testing::test_seed(12)), 128);
  double sum = 0.0;
  for (const Rgb& p : rg.mean.pixels) sum += average(p);
  EXPECT_GT(sum / double(rg.mean.size()), 0.05) << "the box must be lit";
  testing::expect_same_image(rg, rm, "gltf-vs-obj-box", 1e-3, "gltf", "obj");
}

}  // namespace
}  // namespace pathspace
