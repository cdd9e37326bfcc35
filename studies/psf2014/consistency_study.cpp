// The consistency study of issue 15 (Keller, Dahm, Binder 2014, eq. 2: the radius shrinks as
// r0 / n^alpha, so the filtered image converges to the unfiltered expectation): relMSE against spp
// from 1 to 4096, several seeds, for PT, PT + hashed filter (s = 12 px, a fixed voxel size: its bias
// stays) and PT + consistent filter, against a reference of at least 64k spp with its variance of
// the mean. In two steps so that cells can run as separate processes (docs/benchmarks.md):
//
//   consistency_study render SCENE SIZE LABEL SEED MAX_SPP OUT_DIR [THREADS]
//     one progressive render (one RenderSession) of LABEL = pt | hashed | consistent; writes
//     OUT_DIR/<scene>-<label>-s<seed>-p<spp>.exr at every power of two up to MAX_SPP and appends
//     "spp,seconds,mean_neighbours" to OUT_DIR/<scene>-<label>-s<seed>.times.csv.
//   consistency_study measure SCENE REF.exr REF_VAR.exr DIR OUT_PREFIX
//     reads every image of SCENE in DIR and writes OUT_PREFIX.csv (relMSE of each image, debiased by
//     the reference's variance), OUT_PREFIX-bias.csv (per label and spp over the seeds: the mean
//     image's relative squared bias with its noise removed and that estimate's standard error (pixels
//     taken as independent), the reference's own relative noise, and the ratio of the relative squared
//     residual (m - R)^2 to what the noise alone explains (Var m + Var R), 1 without bias) and prints
//     the log-log slope of the seed-mean relMSE over the last decade of spp.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <regex>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "pathspace/film/image_metrics.h"
#include "pathspace/filters/filter_registry.h"
#include "pathspace/io/image_io.h"
#include "pathspace/session/render_session.h"
#include "pathspace/study/experiment.h"
#include "pathspace/study/prepared_scene.h"

using namespace pathspace;
namespace fs = std::filesystem;

namespace {

int usage() {
  std::fprintf(stderr,
               "usage: consistency_study render SCENE SIZE pt|hashed|consistent SEED MAX_SPP OUT_DIR [THREADS]\n"
               "       consistency_study measure SCENE REF.exr REF_VAR.exr DIR OUT_PREFIX\n");
  return 2;
}

// "cornell-box" for a built-in scene, the file's stem for a scene file.
std::string scene_stem(const std::string& scene) {
  const fs::path p(scene);
  return p.has_extension() ? p.parent_path().filename().string() + "-" + p.stem().string() : scene;
}

RenderConfig config_for(const std::string& label) {
  OptionValues values;
  if (label == "pt") return study::configuration(label, "pt", FilterChoice::kNone, values).render;
  if (label == "hashed") {
    values.set("psf-scale", "12");
    return study::configuration(label, "pt", "hashed", values).render;
  }
  if (label == "consistent") return study::configuration(label, "pt", "consistent", values).render;
  throw Error("unknown configuration '" + label + "' (pt, hashed, consistent)");
}

int render(int argc, char** argv) {
  if (argc < 8) return usage();
  const std::string scene = argv[2], label = argv[4], out_dir = argv[7];
  const int size = std::stoi(argv[3]);
  const uint64_t seed = std::stoull(argv[5]);
  const uint32_t max_spp = uint32_t(std::stoul(argv[6]));
  RenderConfig config = config_for(label);
  config.seed = seed;
  config.threads = argc > 8 ? std::stoi(argv[8]) : 0;
  const study::PreparedScene prepared = study::load_prepared_scene({scene, size, size});
  RenderSession session(prepared.scene, prepared.accel, config);
  fs::create_directories(out_dir);
  const std::string base = fmt::format("{}/{}-{}-s{}", out_dir, scene_stem(scene), label, seed);
  std::FILE* times = std::fopen((base + ".times.csv").c_str(), "w");
  if (!times) throw Error("cannot write " + base + ".times.csv");
  std::fprintf(times, "spp,seconds,mean_neighbours\n");
  for (uint32_t spp = 1; spp <= max_spp; spp *= 2) {
    session.run(RunLimit::for_passes(spp - session.passes_done()));
    const RenderSnapshot snap = session.snapshot();
    write_image(fmt::format("{}-p{}.exr", base, spp), snap.mean);
    const Statistic* neighbours = snap.stats.details.find("consistent.mean_neighbours");
    std::fprintf(times, "%u,%.3f,%.4g\n", spp, snap.stats.wall_s, neighbours ? neighbours->number : 0.0);
    std::fflush(times);
  }
  std::fclose(times);
  return 0;
}

struct Cell {
  std::string label;
  uint64_t seed = 0;
  uint32_t spp = 0;
  std::string path;
};

int measure(int argc, char** argv) {
  if (argc < 7) return usage();
  const std::string stem = scene_stem(argv[2]), dir = argv[5], prefix = argv[6];
  const Image reference = read_image(argv[3]), variance = read_image(argv[4]);
  const std::regex name(std::regex_replace(stem, std::regex(R"([.^$|()\[\]{}*+?\\-])"), R"(\$&)") +
                        R"(-(pt|hashed|consistent)-s(\d+)-p(\d+)\.exr)");
  std::vector<Cell> cells;
  for (const fs::directory_entry& e : fs::directory_iterator(dir)) {
    std::smatch m;
    const std::string file = e.path().filename().string();
    if (std::regex_match(file, m, name))
      cells.push_back({m[1], std::stoull(m[2]), uint32_t(std::stoul(m[3])), e.path().string()});
  }
  if (cells.empty()) throw Error("no images of " + stem + " in " + dir);

  std::FILE* rows = std::fopen((prefix + ".csv").c_str(), "w");
  if (!rows) throw Error("cannot write " + prefix + ".csv");
  std::fprintf(rows, "scene,label,seed,spp,rel_mse,rel_mse_debiased\n");
  // label -> spp -> per-pixel sums over seeds (sum, sum of squares) and the seed-mean relMSE.
  struct Sums {
    std::vector<double> sum, sum_sq;
    double rel_mse = 0.0;
    int seeds = 0;
  };
  std::map<std::string, std::map<uint32_t, Sums>> groups;
  const size_t n = 3 * reference.size();
  for (const Cell& c : cells) {
    const Image image = read_image(c.path);
    const ImageError plain = image_error(image, reference), debiased = image_error(image, reference, &variance);
    std::fprintf(rows, "%s,%s,%llu,%u,%.6g,%.6g\n", stem.c_str(), c.label.c_str(), (unsigned long long)c.seed, c.spp, plain.rel_mse,
                 debiased.rel_mse);
    Sums& s = groups[c.label][c.spp];
    if (s.sum.empty()) s.sum.assign(n, 0.0), s.sum_sq.assign(n, 0.0);
    for (size_t i = 0; i < reference.size(); ++i)
      for (int ch = 0; ch < 3; ++ch) {
        const double x = image.pixels[i][ch];
        s.sum[3 * i + ch] += x;
        s.sum_sq[3 * i + ch] += x * x;
      }
    s.rel_mse += debiased.rel_mse;
    ++s.seeds;
  }
  std::fclose(rows);

  std::FILE* bias = std::fopen((prefix + "-bias.csv").c_str(), "w");
  if (!bias) throw Error("cannot write " + prefix + "-bias.csv");
  std::fprintf(bias, "scene,label,spp,seeds,mean_rel_mse,rel_bias_sq,rel_bias_sq_se,reference_rel_noise,residual_ratio\n");
  for (auto& [label, by_spp] : groups) {
    std::vector<std::pair<double, double>> curve;  // log spp, log seed-mean relMSE
    for (auto& [spp, s] : by_spp) {
      const double k = s.seeds;
      double rel_bias_sq = 0.0, bias_term_sq = 0.0, ref_noise = 0.0, residual = 0.0, explained = 0.0;
      for (size_t j = 0; j < n; ++j) {
        const double r = reference.pixels[j / 3][int(j % 3)], v_ref = variance.pixels[j / 3][int(j % 3)];
        const double m = s.sum[j] / k;
        // Unbiased sample variance of one seed's pixel, then of the mean over the seeds.
        const double v_mean = k > 1 ? std::max(0.0, (s.sum_sq[j] - k * m * m) / (k - 1)) / k : 0.0;
        const double d2 = (m - r) * (m - r), w = 1.0 / (r * r + kRelMseEpsilon);
        const double term = (d2 - v_mean - v_ref) * w;
        rel_bias_sq += term;
        bias_term_sq += term * term;
        ref_noise += v_ref * w;
        residual += d2 * w;
        explained += (v_mean + v_ref) * w;
      }
      const double nn = double(n), mean_term = rel_bias_sq / nn;
      const double se = std::sqrt(std::max(0.0, bias_term_sq / nn - mean_term * mean_term) / (nn - 1));
      s.rel_mse /= k;
      std::fprintf(bias, "%s,%s,%u,%d,%.6g,%.6g,%.3g,%.6g,%.4f\n", stem.c_str(), label.c_str(), spp, s.seeds, s.rel_mse, mean_term, se,
                   ref_noise / nn, explained > 0 ? residual / explained : 0.0);
      if (s.rel_mse > 0) curve.emplace_back(std::log(double(spp)), std::log(s.rel_mse));
    }
    // Least-squares slope over the last decade (spp >= max / 10).
    if (curve.size() >= 2) {
      const double last = curve.back().first;
      double sx = 0, sy = 0, sxx = 0, sxy = 0, m = 0;
      for (const auto& [x, y] : curve)
        if (x >= last - std::log(10.0)) sx += x, sy += y, sxx += x * x, sxy += x * y, ++m;
      const double slope = m >= 2 ? (m * sxy - sx * sy) / (m * sxx - sx * sx) : 0.0;
      std::printf("%s %s: seed-mean relMSE %.4g at %u spp, log-log slope over the last decade %.3f\n", stem.c_str(), label.c_str(),
                  by_spp.rbegin()->second.rel_mse, by_spp.rbegin()->first, slope);
    }
  }
  std::fclose(bias);
  std::printf("wrote %s.csv and %s-bias.csv\n", prefix.c_str(), prefix.c_str());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) return usage();
  try {
    const std::string mode = argv[1];
    if (mode == "render") return render(argc, argv);
    if (mode == "measure") return measure(argc, argv);
    return usage();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "consistency_study: %s\n", e.what());
    return 1;
  }
}
