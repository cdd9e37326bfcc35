#include "pathspace/study/prepared_scene.h"

#include <filesystem>

#include "pathspace/accel/accel.h"
#include "pathspace/base/error.h"
#include "pathspace/film/image_metrics.h"
#include "pathspace/io/scene_loader.h"
#include "pathspace/scene/builtin_scenes.h"

namespace pathspace::study {

double reference_noise(const Image& reference, const Image& variance) {
  if (variance.size() != reference.size()) return 0.0;
  double sum = 0.0;
  for (size_t i = 0; i < reference.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      const double r = reference.pixels[i][c];
      sum += double(variance.pixels[i][c]) / (r * r + kRelMseEpsilon);
    }
  return reference.size() ? sum / (3.0 * double(reference.size())) : 0.0;
}

PreparedScene load_prepared_scene(const SceneSpec& spec) {
  if (spec.width < 1 || spec.height < 1) throw Error("study: scene '" + spec.name + "' needs a positive width and height");
  PreparedScene p;
  std::shared_ptr<Scene> scene;
  if (const BuiltinSceneInfo* info = find_builtin_scene(spec.name)) {
    p.summary.id = info->id;
    p.summary.name = info->name;
    scene = std::make_shared<Scene>(make_builtin_scene(info->name, spec.width, spec.height));
  } else if (is_scene_file(spec.name)) {
    p.summary.id = std::filesystem::path(spec.name).stem().string();
    p.summary.name = spec.name;
    SceneLoadOptions options;
    options.width = spec.width;
    options.height = spec.height;
    std::vector<std::string> warnings;
    scene = std::make_shared<Scene>(load_scene(spec.name, options, &warnings));
  } else {
    throw Error("study: '" + spec.name + "' is neither a built-in scene nor a scene file");
  }
  p.summary.width = scene->camera.width;
  p.summary.height = scene->camera.height;
  p.summary.light_count = scene->lights.size();
  p.accel = std::make_shared<Accel>(*scene);
  p.scene = std::move(scene);
  return p;
}

}  // namespace pathspace::study
