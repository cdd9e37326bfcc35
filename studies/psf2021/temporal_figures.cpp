// The hashed filter's table across frames in `pathspace study psf` (studies/psf/psf_figures.h; Binder,
// Fricke, Keller 2021, sec. 3.4; docs/animation.md): the acceptance measurements of the temporal
// reuse, rendered once per study through render_frames (session/frame_sequence.h):
//   * sec. 3.4.1: a static scene seen by an orbiting camera, 1 spp per frame, `--temporal integrate`
//     against `off`, relMSE per frame against a PT reference of that frame;
//   * fig. 9: cornell-moving-light without jitter, ema, integrate and hybrid at frame 32, the error in
//     the band where the lighting moved and over the whole image;
//   * sec. 3.4.3: a camera flight through textured-room with a table too small for the room, for each
//     eviction policy: occupancy, evictions, failed inserts and the resident memory per frame.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "pathspace/accel/accel.h"
#include "pathspace/base/error.h"
#include "pathspace/film/image_metrics.h"
#include "pathspace/io/scene_loader.h"
#include "pathspace/math/rgb.h"
#include "pathspace/scene/builtin_scenes.h"
#include "pathspace/session/frame_sequence.h"
#include "pathspace/study/image_files.h"
#include "studies/psf/psf_figures.h"
#include "pathspace/options/usage_error.h"

namespace pathspace::studies {

namespace {

using study::Measurement;
using study::Record;

void progress(const study::ExperimentRunner& runner, const std::string& line) {
  if (runner.options().quiet) return;
  fmt::print("study: {}\n", line);
  std::fflush(stdout);
}

// The process's resident memory in MiB (/proc/self/status VmRSS; 0 where there is none).
double resident_mib() {
  std::ifstream in("/proc/self/status");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("VmRSS:", 0) == 0) return std::stod(line.substr(6)) / 1024.0;  // kB
  return 0.0;
}

struct FrameReference {
  Image mean, variance;
  double seconds = 0.0;
  uint32_t spp = 0;
  uint64_t seed = 0;
  double noise = 0.0;  // its own relMSE (prepared_scene.h)
};

// Plain PT for `seconds` on one frame's scene.
FrameReference render_reference(const Scene& scene, double seconds, uint64_t seed, int threads) {
  auto shared = std::make_shared<const Scene>(scene);
  auto accel = std::make_shared<const Accel>(*shared);
  RenderConfig config = study::reference_render_config("pt");
  config.seed = seed;
  config.threads = threads;
  RenderSession session(shared, accel, config);
  session.run(RunLimit::for_seconds(seconds));
  RenderSnapshot snap = session.snapshot();
  FrameReference r;
  r.mean = std::move(snap.mean);
  r.variance = std::move(snap.variance);
  r.seconds = snap.stats.wall_s;
  r.spp = snap.stats.spp;
  r.seed = seed;
  r.noise = study::reference_noise(r.mean, r.variance);
  return r;
}

// A scene entry of the page and study.json for one frame's reference (its PNG is that frame's).
study::SceneSummary frame_summary(const study::ExperimentRunner& runner, const std::string& id, const std::string& name,
                                  const Scene& scene, const FrameReference& ref) {
  study::SceneSummary s;
  s.id = id;
  s.name = name;
  s.width = ref.mean.width;
  s.height = ref.mean.height;
  s.light_count = scene.lights.size();
  s.reference.set("integrator", "pt");
  s.reference.set("time_s", ref.seconds);
  s.reference.set("iterations", ref.spp);
  s.reference.set("seed", ref.seed);
  s.reference.set("noise_rel_mse", ref.noise);
  const study::RunnerOptions& o = runner.options();
  if (!o.out_dir.empty()) {
    const study::ImageFiles files = study::write_images(o.out_dir, "images/" + id + "-reference", ref.mean, Image(), o.write_exr);
    s.reference_png = files.png;
    s.reference.set("image_png", files.png);
    if (!files.exr.empty()) s.reference.set("image_exr", files.exr);
  }
  return s;
}

// Option names and values as the command line gives them ("" for a flag).
using OptionList = std::vector<std::pair<std::string, std::string>>;
// Named option lists: the modes and variants of a figure.
using NamedOptions = std::vector<std::pair<std::string, OptionList>>;

study::Configuration hashed_config(const std::string& label, const OptionList& options) {
  OptionValues values;
  for (const auto& [name, value] : options) values.set(name, value);
  return study::configuration(label, "pt", "hashed", values);
}

// A frame's image as a run of the figure, measured against that frame's reference.
Measurement frame_measurement(const study::ExperimentRunner& runner, const std::string& figure, const std::string& scene_id,
                              const study::Configuration& c, uint64_t seed, const Image& image, const FrameReference& ref,
                              double time_s) {
  Measurement m;
  m.experiment = figure;
  m.scene_id = scene_id;
  m.label = c.label;
  m.integrator = c.render.integrator;
  m.filter = c.render.filter.name;
  m.settings = c.settings;
  m.seed = seed;
  m.time_s = time_s;
  m.iterations = 1;
  m.error = image_error(image, ref.mean);
  const ImageError debiased = image_error(image, ref.mean, &ref.variance);
  m.rel_mse_debiased = debiased.rel_mse;
  m.mse_debiased = debiased.mse;
  const study::RunnerOptions& o = runner.options();
  if (!o.out_dir.empty()) {
    const study::ImageFiles files = study::write_images(
        o.out_dir, fmt::format("images/{}-{}-{}", scene_id, study::slug(figure), study::slug(c.label)), image, ref.mean, o.write_exr);
    m.image_png = files.png;
    m.error_png = files.error_png;
    m.image_exr = files.exr;
  }
  return m;
}

// Renders frames 0..last of `animation` at 1 spp; on_frame(frame, result).
void render_sequence(const Animation& animation, const study::Configuration& c, uint64_t seed, int threads, uint64_t last,
                     const std::function<void(const FrameResult&)>& on_frame) {
  RenderConfig config = c.render;
  config.seed = seed;
  config.threads = threads;
  render_frames(animation, config, FrameRange{0, last}, 1, [&](const FrameResult& f) {
    on_frame(f);
    return true;
  });
}

double ratio(double a, double b) { return b != 0.0 ? a / b : 0.0; }

// ---------------------------------------------------------------------------------------------
// Sec. 3.4.1: static scenes, orbiting camera.

struct OrbitScene {
  std::string id, name;
  float degrees_per_frame = 1.f;
  Scene scene;
};

// The orbit's configurations, named by mode. The first two at the filter's defaults (s = 12 px
// voxels). Then the table as a sequence of 1-spp frames would use it: voxels of s = 4 px, noisy in
// one frame, which integration averages away while s = 12 px keeps its blur for ever, and the
// camera hits' textures averaged over their pixels (scene/texture_footprint.h), since a texture
// finer than the pixels aliases in every frame alike and no table of path space averages removes
// that; the last adds 7 query-only anti-aliasing paths per pixel (hashed_filter_query.cpp) for the
// edges, which one primary hit per pixel aliases in every frame too.
constexpr const char* kTemporalScale = "4";
constexpr const char* kTemporalQueries = "7";
std::vector<study::Configuration> orbit_configurations() {
  const std::pair<std::string, std::string> scale{"psf-scale", kTemporalScale}, footprint{"texture-footprint", ""};
  return {hashed_config("integrate", {{"temporal", "integrate"}}),
          hashed_config("off", {{"temporal", "off"}}),
          hashed_config("integrate, s 4, footprint", {{"temporal", "integrate"}, scale, footprint}),
          hashed_config("off, s 4, footprint", {{"temporal", "off"}, scale, footprint}),
          hashed_config("integrate, s 4, footprint, 7 queries", {{"temporal", "integrate"}, scale, footprint, {"psf-aa-paths", kTemporalQueries}})};
}

// Frames (1-based) whose error is measured: the powers of two up to `frames`, and `frames`.
std::vector<uint32_t> measured_frames(uint32_t frames) {
  std::vector<uint32_t> out;
  for (uint32_t f = 1; f < frames; f *= 2) out.push_back(f);
  out.push_back(frames);
  return out;
}

void run_orbit(const study::ExperimentRunner& runner, const TemporalStudyParams& p, double reference_s, study::Figure* fig,
               std::vector<study::SceneSummary>* scenes) {
  const int threads = runner.options().threads;
  std::vector<OrbitScene> orbit_scenes;
  orbit_scenes.push_back({"bs_c", "cornell-box", 0.25f, make_builtin_scene("cornell-box", p.width, p.height)});
  {
    SceneLoadOptions options;
    options.width = p.width;
    options.height = p.height;
    std::vector<std::string> warnings;
    orbit_scenes.push_back({"textured-room", p.room_scene, 1.f, load_scene(p.room_scene, options, &warnings)});
  }
  const std::vector<uint32_t> frames = measured_frames(p.frames);
  const std::vector<study::Configuration> configs = orbit_configurations();
  study::Table table, summary;
  table.comments = {"relMSE of each measured frame (1-based) against a PT reference of that frame; debiased: minus the reference's noise"};
  summary.column("scene").column("mode").column("relMSE frame 1", "{:.4g}", "first").column(fmt::format("relMSE frame {}", p.frames), "{:.4g}", "last")
      .column("frame 1 / last", "{:.2f}", "ratio").column("debiased frame 1", "{:.4g}", "first_debiased")
      .column("debiased last", "{:.4g}", "last_debiased").column("debiased ratio", "{:.2f}", "ratio_debiased");
  std::string finding;
  for (const OrbitScene& os : orbit_scenes) {
    Animation animation;
    animation.scene_at = [&os](double) { return os.scene; };
    animation.orbit_degrees_per_frame = os.degrees_per_frame;
    progress(runner, fmt::format("temporal orbit {}: {} PT references of {:.3g} s", os.name, frames.size(), reference_s));
    std::vector<FrameReference> refs;
    for (uint32_t f : frames) refs.push_back(render_reference(animation.at_frame(f - 1), reference_s, p.seed + study::kReferenceSeedOffset + f, threads));
    for (size_t i = 0; i < frames.size(); i += std::max<size_t>(1, frames.size() - 1))
        scenes->push_back(frame_summary(runner, fmt::format("{}-orbit-f{}", os.id, frames[i]),
                                        fmt::format("{}, orbit {:g} degrees per frame, frame {}", os.name, os.degrees_per_frame, frames[i]),
                                        os.scene, refs[i]));
    study::LinePlot plot;
    plot.title = fmt::format("{}: relMSE per frame, orbit {:g} deg/frame, 1 spp", os.id, os.degrees_per_frame);
    plot.x_label = "frame";
    plot.y_label = "relMSE (debiased)";
    plot.x_scale = plot.y_scale = study::AxisScale::log;
    for (size_t c = 0; c < configs.size(); ++c) {
      std::vector<double> errors, debiased;
      double seconds = 0.0;
      size_t next = 0;
      render_sequence(animation, configs[c], p.seed, threads, p.frames - 1, [&](const FrameResult& f) {
        seconds += f.render_seconds;
        if (next >= frames.size() || f.frame + 1 != frames[next]) return;
        const FrameReference& ref = refs[next];
        const Image& img = f.snapshot.mean;
        const ImageError e = image_error(img, ref.mean), d = image_error(img, ref.mean, &ref.variance);
        errors.push_back(e.rel_mse);
        debiased.push_back(d.rel_mse);
        Record row;
        row.set("scene", os.id).set("mode", configs[c].label).set("frame", f.frame + 1).set("rel_mse", e.rel_mse).set("rel_mse_debiased", d.rel_mse);
        row.set("reference_noise", ref.noise).set("reference_spp", ref.spp);
        table.rows.push_back(std::move(row));
        if (next == 0 || next + 1 == frames.size())
          fig->runs.push_back(frame_measurement(runner, fig->id, fmt::format("{}-orbit-f{}", os.id, frames[next]), configs[c], p.seed, img,
                                                ref, seconds));
        ++next;
      });
      study::PlotSeries s;
      s.name = configs[c].label;
      for (size_t i = 0; i < debiased.size(); ++i) s.points.push_back({double(frames[i]), debiased[i]});
      plot.series.push_back(std::move(s));
      Record row;
      row.set("scene", os.id).set("mode", configs[c].label).set("first", errors.front()).set("last", errors.back())
          .set("ratio", ratio(errors.front(), errors.back())).set("first_debiased", debiased.front()).set("last_debiased", debiased.back())
          .set("ratio_debiased", ratio(debiased.front(), debiased.back()));
      summary.rows.push_back(std::move(row));
      finding += fmt::format("{}{} {}: relMSE frame 1 {:.4g}, frame {} {:.4g} ({:.2f}x lower; debiased {:.4g} -> {:.4g}, {:.2f}x).",
                             finding.empty() ? "" : " ", os.id, configs[c].label, errors.front(), p.frames, errors.back(),
                             ratio(errors.front(), errors.back()), debiased.front(), debiased.back(),
                             ratio(debiased.front(), debiased.back()));
    }
    study::PlotSeries noise;
    noise.name = "reference noise";
    for (size_t i = 0; i < refs.size(); ++i) noise.points.push_back({double(frames[i]), refs[i].noise});
    plot.series.push_back(std::move(noise));
    fig->plots.push_back(study::svg_line_plot(plot));
    finding += fmt::format(" References: PT, {}-{} spp (noise relMSE {:.3g} at frame 1).", refs.front().spp, refs.back().spp,
                           refs.front().noise);
  }
  fig->findings[""] = finding + fmt::format(" Acceptance: integrate at least 4x lower at the last frame than at frame 1, off flat "
                                            "(1 path per pixel and frame: the modes with s {} and the footprint; the last mode adds {} "
                                            "primary rays per pixel).", kTemporalScale, kTemporalQueries);
  fig->data["temporal_orbit"] = table;
  fig->data["temporal_orbit_summary"] = summary;
  fig->shown_tables.push_back({"relMSE at the first and the last frame", summary});
}

// ---------------------------------------------------------------------------------------------
// Fig. 9: the moving light.

constexpr double kBandChange = 0.2;  // a pixel is in the band when its reference changed by more than this
// ... and is not the light itself: the light box's bottom (radiance 25) moves too, and its edge
// pixels' 1-spp aliasing, which no filter touches, would dominate the band; lit surfaces stay below 1.
constexpr float kEmitterLuminance = 1.f;

void run_fig9(const study::ExperimentRunner& runner, const TemporalStudyParams& p, double reference_s, study::Figure* fig,
              std::vector<study::SceneSummary>* scenes) {
  const int threads = runner.options().threads;
  const uint32_t last = std::min<uint32_t>(32, p.frames), before = last >= 8 ? last - 8 : 0;
  Animation animation;
  const int w = p.width, h = p.height;
  animation.scene_at = [w, h](double t) { return make_builtin_scene_at("cornell-moving-light", w, h, t); };
  progress(runner, fmt::format("temporal fig. 9: PT references of frames {} and {}, {:.3g} s each", before, last, reference_s));
  const Scene last_scene = animation.at_frame(last);
  const FrameReference ref = render_reference(last_scene, reference_s, p.seed + study::kReferenceSeedOffset + 1000 + last, threads);
  const FrameReference ref_before =
      render_reference(animation.at_frame(before), reference_s, p.seed + study::kReferenceSeedOffset + 1000 + before, threads);
  const std::string scene_id = fmt::format("ml_c-f{}", last);
  scenes->push_back(frame_summary(runner, scene_id, fmt::format("cornell-moving-light, frame {}", last), last_scene, ref));

  std::vector<uint8_t> band(ref.mean.size());
  size_t in_band = 0;
  std::vector<size_t> band_per_row(size_t(h), 0);
  for (size_t i = 0; i < band.size(); ++i) {
    const float a = luminance(ref.mean.pixels[i]), b = luminance(ref_before.mean.pixels[i]);
    band[i] = std::fabs(a - b) > kBandChange * std::max(a, b) && std::max(a, b) < kEmitterLuminance;
    in_band += band[i];
    band_per_row[i / size_t(w)] += band[i];
  }
  const size_t row = size_t(std::max_element(band_per_row.begin(), band_per_row.end()) - band_per_row.begin());
  // relMSE of the luminance over the band, and the reference's own share of it (its variance of the
  // luminance, channels taken as independent).
  const auto band_error = [&](const Image& img, double* noise) {
    double sum = 0.0, var = 0.0;
    for (size_t i = 0; i < img.size(); ++i) {
      if (!band[i]) continue;
      const double r = luminance(ref.mean.pixels[i]), d = luminance(img.pixels[i]) - r, denom = r * r + kRelMseEpsilon;
      const Rgb& v = ref.variance.pixels[i];
      sum += d * d / denom;
      var += (0.212671 * 0.212671 * v.r + 0.715160 * 0.715160 * v.g + 0.072169 * 0.072169 * v.b) / denom;
    }
    if (noise) *noise = in_band ? var / double(in_band) : 0.0;
    return in_band ? sum / double(in_band) : 0.0;
  };
  double band_noise = 0.0;
  band_error(ref.mean, &band_noise);

  // Fig. 9's three modes, and hybrid with its histories rectified by the probes' ratio (beyond the paper).
  const NamedOptions modes = {
      {"ema", {{"temporal", "ema"}}},
      {"integrate", {{"temporal", "integrate"}}},
      {"hybrid", {{"temporal", "hybrid"}}},
      {"hybrid, rectified", {{"temporal", "hybrid"}, {"temporal-rectify", ""}}}};
  study::Table table;
  table.column("mode").column("band relMSE", "{:.4g}", "band_rel_mse").column("band relMSE debiased", "{:.4g}", "band_rel_mse_debiased")
      .column("relMSE", "{:.4g}", "rel_mse").column("relMSE debiased", "{:.4g}", "rel_mse_debiased")
      .column("mean alpha, last frame", "{:.3f}", "mean_alpha_last");
  study::LinePlot alpha_plot;
  alpha_plot.title = "cornell-moving-light: mean alpha of each frame's step";
  alpha_plot.x_label = "frame";
  alpha_plot.y_label = "mean alpha (weight of the history)";
  study::LinePlot profile;
  profile.title = fmt::format("frame {}: luminance along row {} (most band pixels)", last, row);
  profile.x_label = "pixel x";
  profile.y_label = "luminance";
  {
    study::PlotSeries s{"reference", {}};
    for (int x = 0; x < w; ++x) s.points.push_back({double(x), luminance(ref.mean.at(x, int(row)))});
    profile.series.push_back(std::move(s));
  }
  // At the filter's defaults, then with the voxels and queries of the orbit's last mode (s = 4 px,
  // 7 query paths per pixel: the per-frame error that hybrid is left with is smaller there).
  const NamedOptions variants = {
      {"", {}}, {fmt::format("s {}, {} queries", kTemporalScale, kTemporalQueries), {{"psf-scale", kTemporalScale}, {"psf-aa-paths", kTemporalQueries}}}};
  std::vector<double> bands, whole;  // per variant: ema, integrate, hybrid, hybrid rectified
  for (const auto& [variant, variant_options] : variants) {
    for (const auto& [mode_name, mode_options] : modes) {
      const std::string mode = variant.empty() ? mode_name : mode_name + ", " + variant;
      OptionList options = mode_options;
      options.emplace_back("psf-no-jitter", "");
      options.insert(options.end(), variant_options.begin(), variant_options.end());
      const study::Configuration c = hashed_config("hashed, temporal " + mode, options);
      progress(runner, fmt::format("temporal fig. 9: {} frames 0 to {}", mode, last));
      Image image;
      double seconds = 0.0, alpha_last = 0.0;
      study::PlotSeries alpha{mode, {}};
      render_sequence(animation, c, p.seed, threads, last, [&](const FrameResult& f) {
        seconds += f.render_seconds;
        if (const Statistic* s = f.snapshot.stats.details.find("hashed.temporal.mean_alpha_last")) {
          alpha.points.push_back({double(f.frame), s->number});
          alpha_last = s->number;
        }
        if (f.frame == last) image = f.snapshot.mean;
      });
      double unused = 0.0;
      const double band_rel = band_error(image, &unused);
      Measurement m = frame_measurement(runner, fig->id, scene_id, c, p.seed, image, ref, seconds);
      m.metrics.set("band_rel_mse", band_rel).set("band_rel_mse_debiased", band_rel - band_noise).set("frame", last);
      Record r;
      r.set("mode", mode).set("band_rel_mse", band_rel).set("band_rel_mse_debiased", band_rel - band_noise).set("rel_mse", m.error.rel_mse)
          .set("rel_mse_debiased", m.rel_mse_debiased).set("mean_alpha_last", alpha_last);
      table.rows.push_back(std::move(r));
      bands.push_back(band_rel);
      whole.push_back(m.error.rel_mse);
      study::PlotSeries s{mode, {}};
      for (int x = 0; x < w; ++x) s.points.push_back({double(x), luminance(image.at(x, int(row)))});
      profile.series.push_back(std::move(s));
      alpha_plot.series.push_back(std::move(alpha));
      fig->runs.push_back(std::move(m));
    }
  }
  fig->metric_rows = {{"band_rel_mse", "relMSE in the band", study::MetricFormat::number},
                      {"band_rel_mse_debiased", "band relMSE debiased", study::MetricFormat::number}};
  fig->plots.push_back(study::svg_line_plot(profile));
  fig->plots.push_back(study::svg_line_plot(alpha_plot));
  table.comments = {fmt::format("band: {} pixels whose PT reference changed by more than {:g}% between frames {} and {}; band noise of the "
                                "reference {:.3g}",
                                in_band, 100 * kBandChange, before, last, band_noise)};
  fig->data["temporal_fig9"] = table;
  fig->shown_tables.push_back({fmt::format("frame {}: error in the band ({} pixels) and over the image", last, in_band), table});
  std::string finding = fmt::format("Frame {}, {} pixels in the band (reference change > {:g}% between frames {} and {}; the references' "
                                    "band noise {:.3g}).",
                                    last, in_band, 100 * kBandChange, before, last, band_noise);
  for (size_t v = 0; v < variants.size(); ++v) {
    const double* b = &bands[modes.size() * v];
    const double* e = &whole[modes.size() * v];
    const auto verdict = [&](double hybrid) { return hybrid <= 0.5 * std::min(b[0], b[1]) ? "met" : "not met"; };
    finding += fmt::format(
        " {}: band relMSE ema {:.4g}, integrate {:.4g}, hybrid {:.4g}, rectified {:.4g}; hybrid / ema = {:.2f}, hybrid / integrate = {:.2f} "
        "(acceptance: at most 0.5 for both: {}), rectified / ema = {:.2f}, rectified / integrate = {:.2f} ({}); whole image ema {:.4g}, "
        "integrate {:.4g}, hybrid {:.4g}, rectified {:.4g}.",
        variants[v].first.empty() ? "Defaults" : variants[v].first, b[0], b[1], b[2], b[3], ratio(b[2], b[0]), ratio(b[2], b[1]),
        verdict(b[2]), ratio(b[3], b[0]), ratio(b[3], b[1]), verdict(b[3]), e[0], e[1], e[2], e[3]);
  }
  fig->findings[""] = finding;
}

// ---------------------------------------------------------------------------------------------
// Sec. 3.4.3: the eviction flight.

constexpr int kFlightWidth = 160, kFlightHeight = 90;
constexpr const char* kFlightScale = "3";          // voxel edge in projected pixels
constexpr const char* kFlightTableFactor = "0.25";  // 4096 cells for 14400 pixels
constexpr uint64_t kWarmUpFrames = 100;

// Keyframes every 2 s through eight views of the room (corners, centre, low, high, looking at each
// wall, the floor and the ceiling), repeated until `frames` frames at 30 fps are covered.
CameraPath room_flight(uint64_t frames, double fps) {
  struct View {
    Vec3 position, target;
  };
  const View views[] = {{{1.5f, 1.3f, 1.5f}, {-2.f, 0.8f, -2.f}},   {{0.f, 1.6f, 0.f}, {2.f, 1.f, 0.3f}},
                        {{-1.5f, 1.2f, 1.5f}, {2.f, 0.9f, -2.f}},   {{-1.5f, 1.f, -1.4f}, {2.f, 0.2f, 2.f}},
                        {{0.f, 2.f, -1.2f}, {0.f, 0.f, 1.5f}},      {{1.5f, 1.1f, -1.5f}, {-2.f, 1.2f, 1.8f}},
                        {{0.5f, 0.95f, 0.8f}, {-0.5f, 2.5f, -1.5f}}, {{0.f, 1.2f, 1.8f}, {0.f, 1.1f, -2.f}}};
  constexpr double kSecondsPerView = 2.0;
  CameraPath path;
  const double end = double(frames) / fps + kSecondsPerView;
  for (size_t i = 0; double(i) * kSecondsPerView <= end; ++i) {
    const View& v = views[i % (sizeof(views) / sizeof(views[0]))];
    CameraKeyframe k;
    k.time = double(i) * kSecondsPerView;
    k.position = v.position;
    k.target = v.target;
    path.keys.push_back(k);
  }
  return path;
}

void run_eviction(const study::ExperimentRunner& runner, const TemporalStudyParams& p, study::Figure* fig) {
  const int threads = runner.options().threads;
  SceneLoadOptions options;
  options.width = kFlightWidth;
  options.height = kFlightHeight;
  std::vector<std::string> warnings;
  const Scene room = load_scene(p.room_scene, options, &warnings);
  Animation animation;
  animation.scene_at = [&room](double) { return room; };
  animation.camera_path = room_flight(p.eviction_frames, animation.fps);
  const uint64_t frames = p.eviction_frames, every = std::max<uint64_t>(1, frames / 400);
  const std::vector<std::string> policies = {"priority", "lru", "stale"};

  study::Table per_frame, summary;
  per_frame.comments = {fmt::format("every {}th frame (1-based); vertices and failed inserts of that frame's pass; rss_mib: the process's VmRSS", every)};
  summary.column("policy").column("table cells", "", "cells").column("max occupancy", "{:.4f}", "max_occupancy")
      .column("mean occupancy", "{:.4f}", "mean_occupancy").column("evictions per frame", "{:.1f}", "evicted_per_frame")
      .column("failed inserts after warm-up", "{:.3g}", "failed_share_after_warmup").column("worst frame after warm-up", "{:.3g}", "failed_share_worst_frame")
      .column("RSS frame 100 (MiB)", "{:.1f}", "rss_mib_100").column("RSS last (MiB)", "{:.1f}", "rss_mib_last")
      .column("ms per frame", "{:.2f}", "ms_per_frame").column("temporal ms per step", "{:.3f}", "temporal_ms_per_step")
      .column("filter ms per pass", "{:.3f}", "filter_ms_per_pass").column("temporal share", "{:.3f}", "temporal_share");
  study::LinePlot occupancy, failed, rss;
  occupancy.title = fmt::format("textured-room flight, {}x{}: occupancy after each step", kFlightWidth, kFlightHeight);
  occupancy.x_label = failed.x_label = rss.x_label = "frame";
  occupancy.y_label = "occupied cells / cells";
  failed.title = "failed inserts (probe limit) per frame";
  failed.y_label = "failed inserts / vertices";
  rss.title = "resident memory of the study process";
  rss.y_label = "VmRSS (MiB)";
  std::string finding;
  bool occupancy_met = true, failed_met = true, rss_met = true;
  for (const std::string& policy : policies) {
    const study::Configuration c = hashed_config("hashed, eviction " + policy, {{"temporal", "integrate"},
                                                                       {"temporal-eviction", policy},
                                                                       {"psf-scale", kFlightScale},
                                                                       {"psf-table-factor", kFlightTableFactor}});
    progress(runner, fmt::format("temporal eviction flight, {}: {} frames at {}x{}", policy, frames, kFlightWidth, kFlightHeight));
    study::PlotSeries occ{policy, {}}, fail{policy, {}}, mem{policy, {}};
    double prev_vertices = 0.0, seconds = 0.0, max_occ = 0.0, sum_occ = 0.0, evicted = 0.0;
    double failed_after = 0.0, vertices_after = 0.0, worst = 0.0, rss_100 = 0.0, rss_last = 0.0, cells = 0.0;
    double temporal_s = 0.0, filter_s = 0.0;
    render_sequence(animation, c, p.seed, threads, frames - 1, [&](const FrameResult& f) {
      const Statistics& st = f.snapshot.stats.details;
      const uint64_t frame = f.frame + 1;
      const double all_vertices = st.number("hashed.vertices_per_pass") * st.number("hashed.passes");
      const double vertices = all_vertices - prev_vertices;
      prev_vertices = all_vertices;
      const double occupied = st.number("hashed.occupancy"), fails = st.number("hashed.probe_limit_fallbacks_last");
      const double share = vertices > 0 ? fails / vertices : 0.0;
      cells = st.number("hashed.table_cells");
      seconds += f.render_seconds;
      max_occ = std::max(max_occ, occupied);
      sum_occ += occupied;
      evicted += st.number("hashed.temporal.evicted_last");
      if (frame > kWarmUpFrames) {
        failed_after += fails;
        vertices_after += vertices;
        worst = std::max(worst, share);
      }
      if (frame == std::min<uint64_t>(kWarmUpFrames, frames)) rss_100 = resident_mib();
      if (frame == frames) {
        rss_last = resident_mib();
        temporal_s = st.number("hashed.temporal.s_per_step");
        filter_s = st.number("hashed.clear_s_per_pass") + st.number("hashed.accumulate_s_per_pass") + st.number("hashed.lookup_s_per_pass");
      }
      if (frame % every == 0 || frame == 1 || frame == frames) {
        const double mib = resident_mib();
        occ.points.push_back({double(frame), occupied});
        fail.points.push_back({double(frame), share});
        mem.points.push_back({double(frame), mib});
        Record r;
        r.set("policy", policy).set("frame", frame).set("occupancy", occupied).set("evicted", st.number("hashed.temporal.evicted_last"));
        r.set("vertices", vertices).set("failed_inserts", fails).set("failed_share", share).set("rss_mib", mib).set("render_s", f.render_seconds);
        per_frame.rows.push_back(std::move(r));
      }
    });
    const double target = 0.75;  // --temporal-occupancy's default, used here
    const double failed_share = vertices_after > 0 ? failed_after / vertices_after : 0.0;
    if (policy != "stale" && max_occ > target + 1e-9) occupancy_met = false;
    if (policy != "stale" && failed_share >= 0.01) failed_met = false;  // stale has no occupancy target: it overflows by design
    if (rss_last > rss_100 * 1.05 + 1.0) rss_met = false;
    Record s;
    s.set("policy", policy).set("cells", cells).set("max_occupancy", max_occ).set("mean_occupancy", sum_occ / double(frames))
        .set("evicted_per_frame", evicted / double(frames)).set("failed_share_after_warmup", failed_share)
        .set("failed_share_worst_frame", worst).set("rss_mib_100", rss_100).set("rss_mib_last", rss_last)
        .set("ms_per_frame", 1e3 * seconds / double(frames)).set("temporal_ms_per_step", 1e3 * temporal_s)
        .set("filter_ms_per_pass", 1e3 * filter_s).set("temporal_share", ratio(temporal_s, temporal_s + filter_s));
    summary.rows.push_back(std::move(s));
    finding += fmt::format("{}{}: occupancy at most {:.3f}, {:.1f} evictions per frame, failed inserts after frame {} {:.3g}% of the "
                           "vertices (worst frame {:.3g}%), RSS {:.1f} -> {:.1f} MiB, {:.2f} ms per frame, temporal bookkeeping {:.1f}% "
                           "of the filter's time.",
                           finding.empty() ? "" : " ", policy, max_occ, evicted / double(frames), kWarmUpFrames, 100 * failed_share,
                           100 * worst, rss_100, rss_last, 1e3 * seconds / double(frames), 100 * ratio(temporal_s, temporal_s + filter_s));
    occupancy.series.push_back(std::move(occ));
    failed.series.push_back(std::move(fail));
    rss.series.push_back(std::move(mem));
  }
  fig->plots.push_back(study::svg_line_plot(occupancy));
  fig->plots.push_back(study::svg_line_plot(failed));
  fig->plots.push_back(study::svg_line_plot(rss));
  fig->findings[""] = finding + fmt::format(" Acceptance: occupancy <= 0.75 for priority and lru: {}; failed inserts after warm-up below 1%: "
                                            "{}; RSS flat (within 5%): {}.",
                                            occupancy_met ? "met" : "not met", failed_met ? "met" : "not met", rss_met ? "met" : "not met");
  fig->data["temporal_eviction"] = per_frame;
  fig->data["temporal_eviction_summary"] = summary;
  fig->shown_tables.push_back({fmt::format("{} frames per policy", frames), summary});
}

void skip(study::Figure* fig, const std::string& option) {
  fig->reproduced = false;
  fig->not_reproduced_reason = "Not run in this study: " + option + " 0.";
}

}  // namespace

std::string resolve_room_scene(const std::string& given) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (fs::is_regular_file(given, ec)) return given;
  if (fs::path(given).is_relative()) {
    // The binary lives in the build tree inside the repository (build/apps/pathspace/pathspace).
    const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    if (!ec)
      for (fs::path dir = exe.parent_path(); !dir.empty() && dir != dir.root_path(); dir = dir.parent_path())
        if (fs::is_regular_file(dir / given, ec)) return (dir / given).string();
  }
  throw UsageError("--room-scene: cannot find '" + given + "'",
                   "run 'pathspace study psf' from the repository, give the file's path, or skip the temporal figures with --temporal-frames 0 --eviction-frames 0");
}

void run_temporal_figures(const study::ExperimentRunner& runner, const TemporalStudyParams& p, std::vector<study::Figure>* figures,
                          std::vector<study::SceneSummary>* scenes) {
  study::Figure& orbit = study::find_figure(figures, "2021-sec3.4.1");
  study::Figure& fig9 = study::find_figure(figures, "2021-fig9");
  study::Figure& eviction = study::find_figure(figures, "2021-sec3.4.3");
  // The frames' references share the study's reference time: an eighth of it each.
  const double reference_s = p.reference_s / 8.0;
  if (p.frames > 0) {
    run_orbit(runner, p, reference_s, &orbit, scenes);
    run_fig9(runner, p, reference_s, &fig9, scenes);
  } else {
    skip(&orbit, "--temporal-frames");
    skip(&fig9, "--temporal-frames");
  }
  if (p.eviction_frames > 0)
    run_eviction(runner, p, &eviction);
  else
    skip(&eviction, "--eviction-frames");
}

}  // namespace pathspace::studies
