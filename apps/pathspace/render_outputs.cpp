#include "render_outputs.h"

#include <filesystem>

#include <fmt/format.h>

#include "pathspace/io/atomic_file.h"
#include "pathspace/io/image_io.h"
#include "pathspace/io/scene_loader.h"
#include "pathspace/scene/builtin_scenes.h"
#include "pathspace/options/usage_error.h"

namespace pathspace::cli {

std::vector<std::string> image_output_paths(const std::vector<std::string>& given, const std::string& name) {
  if (!given.empty()) return given;
  constexpr const char* kDefaultOutputFolder = "pathspace-out";
  std::filesystem::create_directories(kDefaultOutputFolder);
  const std::string base = std::string(kDefaultOutputFolder) + "/" + name;
  return {base + ".exr", base + ".png"};
}

void check_image_path(const std::string& option, const std::string& path) {
  try {
    image_format_from_path(path);
  } catch (const Error& e) {
    if (option == "-o" && (find_builtin_scene(path) || is_scene_file(path)))
      throw UsageError("-o took the scene '" + path + "' as an output file: -o reads every word up to the next option, so "
                       "give the scene before -o, or end the outputs with --");
    throw UsageError(e.what());
  }
  check_output_writable(path);
}

std::string aov_path(const std::string& first_image, const std::string& aov) {
  const std::filesystem::path first(first_image);
  return (first.parent_path() / (first.stem().string() + ".aov-" + aov + ".exr")).string();
}

std::vector<std::string> write_outputs(const OutputPlan& plan, const RenderSnapshot& snapshot, OutputKind kind,
                                       const ExtraOutput* extra) {
  const ImageEncoding encoding = kind == OutputKind::periodic ? ImageEncoding::fast : ImageEncoding::compact;
  OutputSet set;
  for (const std::string& path : plan.images) set.add(path, encode_image(path, snapshot.mean, encoding));
  if (!plan.variance.empty()) set.add(plan.variance, encode_image(plan.variance, snapshot.variance, encoding));
  for (const NamedImage& aov : snapshot.aovs) {
    const std::string path = aov_path(plan.images.front(), aov.name);
    set.add(path, encode_image(path, aov.image, encoding));
  }
  std::vector<std::string> written = set.paths();
  if (!plan.stats.empty()) {
    RenderRunInfo run = plan.run;
    run.outputs = fmt::format("{}", fmt::join(written, ","));
    set.add(plan.stats, render_stats_json(snapshot.stats, run));
    written.push_back(plan.stats);
  }
  if (extra) {
    set.add(extra->path, extra->bytes.data(), extra->bytes.size());
    written.push_back(extra->path);
  }
  set.commit();
  return written;
}

}  // namespace pathspace::cli
