// The shipped scenes' forms render the same image (docs/scene-files.md, "Shipped test scenes"):
// independent path-traced renders of the pbrt-v4, Mitsuba 3 and OBJ forms (the fog room, with
// participating media, and the fog lamp have no OBJ form) at 32x32 pass the
// per-pixel z-test against each other. The textured room's OBJ form has no environment light (OBJ
// cannot express one), so it is compared with the pbrt form with its environment removed.
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>

#include "pathspace/io/load_warnings.h"
#include "pathspace/io/pbrt/pbrt_scene_builder.h"
#include "support/integrator_comparison.h"
#include "support/shipped_scenes.h"
#include "support/statistics.h"

namespace pathspace {
namespace {

constexpr int kSize = 32;
constexpr int kComparisons = 6;
const double kAlphaImage = testing::sidak(0.01, kComparisons);

testing::Rendered render(const Scene& scene, uint64_t seed, uint32_t passes, const std::string& integrator = "pt") {
  return testing::render_integrator(scene, testing::default_config(integrator, testing::test_seed(seed)), passes);
}

Scene load(const std::string& scene, const std::string& form) {
  std::vector<std::string> warnings;
  return testing::load_shipped(testing::shipped_scene(scene), form, kSize, kSize, &warnings);
}

TEST(ShippedScenes, GlassCausticFormsRenderTheSameImage) {
  const uint32_t passes = 1024;
  const Scene scene = load("glass-caustic", "scene.pbrt");
  const testing::Rendered pbrt = render(scene, 1, passes);
  expect_same_image(pbrt, render(load("glass-caustic", "scene.xml"), 2, passes), "glass-caustic pbrt vs Mitsuba", kAlphaImage,
                    "pbrt", "xml");
  expect_same_image(pbrt, render(load("glass-caustic", "scene.obj"), 3, passes), "glass-caustic pbrt vs OBJ", kAlphaImage,
                    "pbrt", "obj");
}

TEST(ShippedScenes, FogRoomFormsRenderTheSameImage) {
  const uint32_t passes = 1024;
  expect_same_image(render(load("fog-room", "scene.pbrt"), 1, passes), render(load("fog-room", "scene.xml"), 2, passes),
                    "fog-room pbrt vs Mitsuba", kAlphaImage, "pbrt", "xml");
}

TEST(ShippedScenes, FogLampFormsRenderTheSameImage) {
  const uint32_t passes = 512;
  expect_same_image(render(load("fog-lamp", "scene.pbrt"), 1, passes), render(load("fog-lamp", "scene.xml"), 2, passes),
                    "fog-lamp pbrt vs Mitsuba", kAlphaImage, "pbrt", "xml");
}

TEST(ShippedScenes, TexturedRoomFormsRenderTheSameImage) {
  const uint32_t passes = 512;
  expect_same_image(render(load("textured-room", "scene.pbrt"), 1, passes), render(load("textured-room", "scene.xml"), 2, passes),
                    "textured-room pbrt vs Mitsuba", kAlphaImage, "pbrt", "xml");
  // The pbrt form without its LightSource "infinite" against the OBJ form.
  const std::string folder = testing::shipped_scenes_dir() + "/textured-room";
  std::ifstream in(folder + "/scene.pbrt");
  std::string text((std::istreambuf_iterator<char>(in)), {});
  const size_t env = text.find("LightSource \"infinite\"");
  ASSERT_NE(env, std::string::npos);
  text.insert(env, "# ");
  std::vector<std::string> warnings;
  LoadWarnings w(&warnings);
  SceneLoadOptions o;
  o.width = o.height = kSize;
  const Scene dark = pbrt::load_pbrt_string(text, "scene.pbrt", folder, o, &w, nullptr);
  expect_same_image(render(dark, 3, passes), render(load("textured-room", "scene.obj"), 4, passes),
                    "textured-room pbrt (no environment) vs OBJ", kAlphaImage, "pbrt", "obj");
}

}  // namespace
}  // namespace pathspace
