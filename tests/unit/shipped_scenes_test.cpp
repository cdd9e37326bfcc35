// The shipped test scenes (scenes/): the committed images equal what tools/scene_assets generates
// (so they cannot drift from the code that documents them), and every form of every scene loads
// without warnings into the same geometry.
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>

#include "pathspace/io/image_io.h"
#include "scene_assets.h"
#include "support/shipped_scenes.h"
#include "support/temp_dir.h"

namespace pathspace {
namespace {

std::string file_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// PFM files are our own writer's bytes; PNG files are compared by their 8-bit texels, so that another
// zlib/stb version (a different but equivalent compression) does not count as drift.
TEST(ShippedScenes, CommittedAssetsEqualTheGenerator) {
  testing::TempDir dir("scene-assets");
  for (const scene_assets::Asset& a : scene_assets::all_assets()) {
    const std::string committed = testing::shipped_scenes_dir() + "/" + a.relative_path;
    const std::string fresh = dir.file(std::filesystem::path(a.relative_path).filename().string());
    write_image(fresh, a.image);
    if (a.relative_path.ends_with(".png")) {
      const Image c = read_image(committed, LdrEncoding::linear), f = read_image(fresh, LdrEncoding::linear);
      ASSERT_EQ(c.width, f.width) << committed;
      ASSERT_EQ(c.height, f.height) << committed;
      EXPECT_TRUE(c.pixels == f.pixels) << committed << " differs from tools/scene_assets' output: rerun pathspace-scene-assets";
    } else {
      EXPECT_TRUE(file_bytes(committed) == file_bytes(fresh)) << committed << " differs from tools/scene_assets' output";
    }
  }
}

TEST(ShippedScenes, EveryFormLoadsWithoutWarnings) {
  for (const testing::ShippedScene& s : testing::shipped_scenes()) {
    size_t triangles = 0;
    for (const std::string& form : s.forms) {
      std::vector<std::string> warnings;
      const Scene scene = testing::load_shipped(s, form, 32, 32, &warnings);
      // The one expected warning: pbrt-v4 itself reads only square environment maps.
      const bool lat_long_pbrt = s.name == "textured-room" && form == "scene.pbrt";
      EXPECT_EQ(warnings.size(), lat_long_pbrt ? 1u : 0u) << s.name << "/" << form << ": " << ::testing::PrintToString(warnings);
      if (lat_long_pbrt && warnings.size() == 1) {
        EXPECT_NE(warnings[0].find("read as a pbrt-v3 lat-long map"), std::string::npos);
      }
      if (triangles == 0) triangles = scene.triangles.size();
      EXPECT_EQ(scene.triangles.size(), triangles) << s.name << "/" << form;
      EXPECT_EQ(scene.max_path_segments, 10) << s.name << "/" << form;
      if (s.name == "textured-room") {
        EXPECT_FALSE(scene.textures.empty()) << form;
      }
    }
  }
}

}  // namespace
}  // namespace pathspace
