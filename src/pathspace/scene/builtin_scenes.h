// The built-in scenes: exact copies of SmallVCM's Cornell box variants (docs/scenes.md), selectable
// by SmallVCM's id (e.g. "bs_c") or a descriptive name (e.g. "cornell-box"), and two scenes made to
// test path space filters (scene/filter_scenes.h).
#pragma once

#include <string>
#include <vector>

#include "pathspace/scene/scene.h"

namespace pathspace {

struct BuiltinSceneInfo {
  std::string name;         // descriptive name, e.g. "cornell-box"
  std::string id;           // SmallVCM acronym, e.g. "bs_c"
  unsigned mask;            // LoadCornellBox bit mask
  std::string description;
  Scene (*build)(int width, int height) = nullptr;  // set for scenes that are not Cornell variants
  // Animated scenes: the scene at `seconds` into the animation (build is the scene at 0).
  Scene (*animate)(int width, int height, double seconds) = nullptr;
};

inline constexpr const char* kDefaultSceneName = "cornell-box";

const std::vector<BuiltinSceneInfo>& builtin_scenes();
// Finds a scene by name or id; nullptr when unknown.
const BuiltinSceneInfo* find_builtin_scene(const std::string& name_or_id);
// Builds a finalised scene; throws pathspace::Error for an unknown name.
Scene make_builtin_scene(const std::string& name_or_id, int width = 512, int height = 512);
// The scene `seconds` into its animation; a scene that is not animated is the same at every time.
Scene make_builtin_scene_at(const std::string& name_or_id, int width, int height, double seconds);

// SmallVCM's LoadCornellBox(resolution, mask) bits (docs/scenes.md §1).
enum CornellMask : unsigned {
  kLightCeiling = 1,
  kLightSun = 2,
  kLightPoint = 4,
  kLightBackground = 8,
  kLargeMirrorSphere = 16,
  kLargeGlassSphere = 32,
  kSmallMirrorSphere = 64,
  kSmallGlassSphere = 128,
  kGlossyFloor = 256,
};
// light_offset moves the light box (the animated scenes of scene/animated_scenes.h), whose
// kLightBoxTriangles triangles are the last ones added.
inline constexpr uint32_t kLightBoxTriangles = 10;
Scene make_cornell_box(unsigned mask, int width, int height, const Vec3& light_offset = Vec3());

}  // namespace pathspace
