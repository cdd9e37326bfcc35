#include "pathspace/session/render_stats_json.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "pathspace/scene/scene.h"
#include "pathspace/session/render.h"

namespace pathspace {

int max_segments_of(const OptionValues& given, const Scene& scene) {
  const std::string* depth = given.find("max-depth");
  return depth ? std::stoi(*depth) : scene.max_path_segments;
}

nlohmann::ordered_json render_stats_object(const RenderStats& stats, const RenderRunInfo& run) {
  nlohmann::ordered_json j;
  j["scene"] = run.scene;
  j["integrator"] = stats.integrator;
  j["width"] = run.width;
  j["height"] = run.height;
  j["max_segments"] = run.max_segments;
  j["spp"] = stats.spp;
  j["wall_time_s"] = stats.wall_s;
  j["rays"] = stats.rays;
  j["shadow_rays"] = stats.shadow_rays;
  j["paths"] = stats.paths;
  j["mrays_per_s"] = stats.mrays_per_s();
  j["paths_per_s"] = stats.paths_per_s();
  j["samples_per_s"] = stats.wall_s > 0 ? double(stats.spp) * run.width * run.height / stats.wall_s : 0.0;
  j["dropped_nan_inf_samples"] = stats.dropped_samples;
  j["threads"] = stats.threads;
  j["seed"] = stats.seed;
  j["build_type"] = build_type();
  j["outputs"] = run.outputs;
  j["filter"] = stats.filter;
  j["statistics"] = statistics_json(stats.details);
  // Only in a distributed render, so a single process's JSON is as before.
  if (!stats.ranks.empty()) {
    nlohmann::ordered_json ranks = nlohmann::ordered_json::array();
    for (size_t r = 0; r < stats.ranks.size(); ++r) {
      const RankStats& s = stats.ranks[r];
      ranks.push_back({{"rank", r}, {"passes", s.passes}, {"threads", s.threads}, {"wall_time_s", s.wall_s},
                       {"exchange_s", s.exchange_s}, {"rays", s.rays}, {"paths", s.paths}, {"bytes_sent", s.bytes_sent}});
    }
    j["ranks"] = ranks;
  }
  return j;
}

std::string render_stats_json(const RenderStats& stats, const RenderRunInfo& run) {
  return render_stats_object(stats, run).dump(2) + "\n";
}

std::string format_rank_table(const RenderStats& stats) {
  std::string out;
  for (size_t r = 0; r < stats.ranks.size(); ++r) {
    const RankStats& s = stats.ranks[r];
    out += fmt::format("  rank {}: {} passes, {} threads, {:.2f} s ({:.2f} s exchanging), {:.3g} paths, {:.1f} MiB sent\n", r, s.passes,
                       s.threads, s.wall_s, s.exchange_s, double(s.paths), double(s.bytes_sent) / 1048576.0);
  }
  return out;
}

nlohmann::ordered_json statistics_json(const Statistics& statistics) {
  nlohmann::ordered_json details = nlohmann::ordered_json::object();
  for (const Statistic& s : statistics.all()) {
    if (s.kind == StatKind::histogram)
      details[s.name] = s.bins;
    else if (s.kind == StatKind::text)
      details[s.name] = s.text;
    else if (s.kind == StatKind::counter || s.kind == StatKind::bytes)
      details[s.name] = uint64_t(s.number);
    else
      details[s.name] = s.number;
  }
  return details;
}

}  // namespace pathspace
