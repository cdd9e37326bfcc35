#include "scene_animation.h"

#include <string>
#include <vector>

#include "pathspace/io/scene_loader.h"
#include "pathspace/scene/builtin_scenes.h"

namespace pathspace::cli {

std::function<Scene(double)> scene_animation(const RenderOptions& o, const PreparedScene& prepared) {
  const BuiltinSceneInfo* builtin = prepared.file.empty() ? find_builtin_scene(prepared.label) : nullptr;
  if (builtin && builtin->animate) {
    const int width = prepared.scene.camera.width, height = prepared.scene.camera.height;
    return [&o, builtin, width, height](double seconds) {
      Scene s = builtin->animate(width, height, seconds);
      s.name = builtin->name;
      apply_scene_options(o, &s);
      return s;
    };
  }
  if (prepared.file.empty()) return {};
  // prepare_scene loaded the same file with the same options and printed its warnings, so this
  // load's are dropped.
  std::vector<std::string> printed;
  std::function<Scene(double)> file_scene_at = load_scene_animation(prepared.file, prepared.load_options, &printed);
  if (!file_scene_at) return {};
  return [&o, file_scene_at](double seconds) {
    Scene s = file_scene_at(seconds);
    apply_scene_options(o, &s);
    return s;
  };
}

}  // namespace pathspace::cli
