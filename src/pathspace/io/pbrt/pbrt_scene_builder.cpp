// pbrt-v4 files and strings through the scene builder (pbrt_builder.h); every error names at least
// the file.
#include "pathspace/io/pbrt/pbrt_scene_builder.h"

#include <filesystem>

#include "pathspace/io/pbrt/pbrt_builder.h"
#include "pathspace/io/pbrt/pbrt_parser.h"

namespace pathspace::pbrt {

namespace {
// Every Error from a scene file names at least the file (checks deep in Scene have no location).
// A null `warnings` discards them.
template <typename F>
Scene located(const std::string& name, LoadWarnings* warnings, F&& load) {
  LoadWarnings discard(nullptr);
  try {
    return load(warnings ? warnings : &discard);
  } catch (const Error& e) {
    if (!e.location().file.empty()) throw;
    throw Error(FileLoc{name}, e.what());
  }
}
}  // namespace

Scene load_pbrt_file(const std::string& path, const SceneLoadOptions& options, LoadWarnings* warnings, SceneFileSettings* settings) {
  return located(path, warnings, [&](LoadWarnings* w) {
    SceneBuilder b(options, w, std::filesystem::path(path).parent_path().string());
    parse_file(path, [&](const Statement& st) { b.handle(st); });
    return b.finish(settings);
  });
}

Scene load_pbrt_string(const std::string& text, const std::string& name, const std::string& folder, const SceneLoadOptions& options,
                       LoadWarnings* warnings, SceneFileSettings* settings) {
  return located(name, warnings, [&](LoadWarnings* w) {
    SceneBuilder b(options, w, folder);
    parse_string(text, name, folder, [&](const Statement& st) { b.handle(st); });
    return b.finish(settings);
  });
}

}  // namespace pathspace::pbrt
