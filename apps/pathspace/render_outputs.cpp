#include "render_outputs.h"

#include <filesystem>

#include <fmt/format.h>

#include "pathspace/io/atomic_file.h"
#include "pathspace/io/image_io.h"

namespace pathspace::cli {

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
