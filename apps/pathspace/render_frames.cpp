#include "render_frames.h"

#include <csignal>
#include <filesystem>
#include <optional>
#include <set>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "pathspace/base/printable.h"
#include "pathspace/io/atomic_file.h"
#include "pathspace/io/camera_path_file.h"
#include "pathspace/options/option_parse.h"
#include "pathspace/parallel/background_job.h"
#include "pathspace/session/frame_sequence.h"
#include "distinct_files.h"
#include "frame_pattern.h"
#include "interrupt_handler.h"
#include "job_group.h"
#include "render_outputs.h"
#include "render_scene.h"
#include "scene_animation.h"
#include "pathspace/session/render_stats_json.h"
#include "pathspace/options/usage_error.h"
#include "video_encoder.h"

namespace pathspace::cli {

namespace {

FrameRange parse_frames(const std::string& text) {
  const size_t colon = text.find(':');
  const auto number = [&](const std::string& part) {  // the project's checked parser (options/option_parse.h)
    try {
      return parse_unsigned_option("frames", part, 999999999);
    } catch (const OptionError&) {
      throw UsageError(fmt::format("--frames expects FIRST:LAST, two frame numbers below 10^9, not '{}'", text), "e.g. --frames 0:63");
    }
  };
  if (colon == std::string::npos) throw UsageError(fmt::format("--frames expects FIRST:LAST, not '{}'", text), "e.g. --frames 0:63");
  const FrameRange r{number(text.substr(0, colon)), number(text.substr(colon + 1))};
  if (r.last < r.first) throw UsageError(fmt::format("--frames {}: the last frame comes before the first", text));
  return r;
}

// What a still render has that a sequence does not (yet).
void check_sequence_options(const RenderOptions& o) {
  const std::pair<bool, const char*> unsupported[] = {
      {!o.checkpoint.empty(), "--checkpoint"}, {!o.resume.empty(), "--resume"},   {o.write_every > 0.0, "--write-every"},
      {o.time_s > 0.0, "--time"},              {o.checkpoint_every > 0.0, "--checkpoint-every"}};
  for (const auto& [given, name] : unsupported)
    if (given) throw UsageError(std::string(name) + " does not apply to --frames (a frame's table spans the frames before it)");
}

nlohmann::ordered_json frame_entry(const FrameResult& f, const Animation& animation) {
  nlohmann::ordered_json j;
  j["frame"] = f.frame;
  j["time_s"] = animation.seconds_of(f.frame);
  j["scene_build_s"] = f.scene_seconds;
  j["static_geometry_reused"] = f.static_geometry_reused;
  j["render_s"] = f.render_seconds;
  j["spp"] = f.snapshot.stats.spp;
  j["rays"] = f.snapshot.stats.rays;
  j["seed"] = frame_seed(f.snapshot.stats.seed, f.frame);
  j["statistics"] = statistics_json(f.snapshot.stats.details);
  return j;
}

// The per-frame line: what the table did in the frame's last pass (hashed filter), when it ran.
std::string frame_summary(const Statistics& s) {
  std::string line;
  if (const Statistic* occupancy = s.find("hashed.occupancy")) line += fmt::format(", occupancy {:.3f}", occupancy->number);
  if (const Statistic* evicted = s.find("hashed.temporal.evicted_last")) line += fmt::format(", evicted {}", uint64_t(evicted->number));
  if (const Statistic* failed = s.find("hashed.probe_limit_fallbacks_last")) line += fmt::format(", failed inserts {}", uint64_t(failed->number));
  if (const Statistic* alpha = s.find("hashed.temporal.mean_alpha_last")) line += fmt::format(", mean alpha {:.3f}", alpha->number);
  return line;
}

}  // namespace

int render_frame_sequence(const RenderOptions& o, const RenderConfig& config) {
  // Under mpirun each rank renders a chunk of the frames as a sequence of its own and writes them;
  // rank 0 writes --stats and --video once every rank is done (docs/distributed.md).
  const std::shared_ptr<ProcessGroup> group = job_group();
  const bool root = !group || group->rank() == 0;
  const bool quiet = o.quiet || !root;
  FrameRange range;
  const uint32_t spp = o.spp > 0 ? o.spp : 1;
  std::string ffmpeg;
  std::optional<PreparedScene> prepared_scene;
  std::vector<std::string> images;
  agreed_step(group.get(), [&] {
    check_sequence_options(o);
    range = parse_frames(o.frames);
    if (!o.video.empty() && root) {
      ffmpeg = find_ffmpeg();
      if (ffmpeg.empty()) throw Error("--video needs the ffmpeg program, which is not on PATH (scripts/install-deps installs it)");
      check_output_writable(o.video);
    }
    prepared_scene.emplace(prepare_scene(o));
    images = image_output_paths(o.outputs, prepared_scene->display_name + "-%04d");
    for (const std::string& pattern : images) {
      check_frame_pattern("-o", pattern);
      check_image_path("-o", frame_path(pattern, range.first));
    }
    if (!o.variance_path.empty()) check_frame_pattern("--variance-out", o.variance_path);
    std::vector<NamedFile> once;  // the outputs written once for the whole sequence
    if (!o.stats_path.empty() && root) once.push_back({"--stats", o.stats_path}), check_output_writable(o.stats_path);
    if (!o.video.empty()) once.push_back({"--video", o.video});
    std::vector<NamedFile> inputs = scene_inputs(*prepared_scene);
    if (!o.camera_path.empty()) inputs.push_back({"--camera-path", o.camera_path});
    // Every frame's files, not only the first's: frame 7 of a pattern may be the --stats file.
    for (uint64_t f = range.first; f <= range.last; ++f) {
      std::vector<NamedFile> files;
      for (const std::string& pattern : images) files.push_back({"-o", frame_path(pattern, f)});
      if (!o.variance_path.empty()) files.push_back({"--variance-out", frame_path(o.variance_path, f)});
      files.insert(files.end(), once.begin(), once.end());
      check_distinct_files(files, inputs);
    }
  });
  PreparedScene& prepared = *prepared_scene;

  Animation animation;
  animation.fps = o.fps;
  animation.orbit_degrees_per_frame = o.orbit;
  if (!o.camera_path.empty()) animation.camera_path = read_camera_path(o.camera_path);
  const int width = prepared.scene.camera.width, height = prepared.scene.camera.height;
  animation.scene_at = scene_animation(o, prepared);
  if (!animation.scene_at) animation.scene_at = [&prepared](double) { return prepared.scene; };  // a scene that stands still

  // PNG frames for the video: the -o PNG sequence, else a temporary folder beside the video.
  std::string png_pattern, temporary_pngs;
  if (!o.video.empty()) {
    for (const std::string& p : images)
      if (std::filesystem::path(p).extension() == ".png") png_pattern = p;
    if (png_pattern.empty()) {
      temporary_pngs = (std::filesystem::path(o.video).parent_path() / ("." + std::filesystem::path(o.video).stem().string() + ".frames")).string();
      std::filesystem::create_directories(temporary_pngs);
      png_pattern = temporary_pngs + "/%06d.png";
    }
  }

  if (!quiet) {
    fmt::print("pathspace: {} ({}), {}x{}, {}, frames {} to {} at {} spp", prepared.display_name, prepared.id, width, height,
               o.integrator, range.first, range.last, spp);
    if (group) fmt::print(", {} processes", group->size());
    fmt::print("\n");
  }
  InterruptHandler interrupt(root);
  RenderRunInfo run{prepared.display_name, width, height, 0, ""};
  nlohmann::ordered_json frames = nlohmann::ordered_json::array();
  // Each frame's scene validation warnings (the session's), printed the first time they appear;
  // prepare_scene printed those of the still scene.
  std::set<std::string> printed(prepared.validation_warnings.begin(), prepared.validation_warnings.end());
  const FrameChunk chunk = group ? FrameChunk{group->rank(), group->size()} : FrameChunk{};
  uint64_t rendered = 0;
  // Frame N is encoded and written on a thread of its own while frame N+1 renders (writing a
  // 640x360 EXR and PNG takes about as long as rendering it). One frame is written at a time: the
  // next frame's hand-off waits for it and rethrows its error, so a failed write stops the sequence
  // one frame later. The bytes written are the same as writing in turn.
  BackgroundJob writer;
  try {
    rendered = render_frames(
        animation, config, range, spp,
        [&](FrameResult& f) {
          for (const std::string& w : f.scene_warnings)
            if (printed.insert(w).second) fmt::print(stderr, "{}\n", printable(w));  // by the rank rendering the frame
          if (interrupt.signal() != 0 && f.snapshot.stats.spp < spp) return false;  // an unfinished frame is not written
          OutputPlan plan;
          for (const std::string& p : images) plan.images.push_back(frame_path(p, f.frame));
          if (!temporary_pngs.empty()) plan.images.push_back(frame_path(png_pattern, f.frame));
          if (!o.variance_path.empty()) plan.variance = frame_path(o.variance_path, f.frame);
          plan.run = run;
          frames.push_back(frame_entry(f, animation));
          // Every rank's frames are its own: each prints its lines.
          if (!o.quiet) fmt::print("frame {}: {:.3f} s{}\n", f.frame, f.render_seconds, frame_summary(f.snapshot.stats.details));
          writer.start([plan = std::move(plan), snapshot = std::move(f.snapshot)] { write_outputs(plan, snapshot, OutputKind::final); });
          return interrupt.signal() == 0;
        },
        [&](RenderSession& session) { interrupt.watch(&session); }, chunk,
        o.variance_path.empty() ? SnapshotImages::mean : SnapshotImages::mean_and_variance);
    writer.wait();  // the last frame's files, before --stats, --video and the other ranks count on them
  } catch (const std::exception& e) {
    // Rank 0 waits for the others' frames at the end: a failure on one rank ends the job.
    if (group) abort_job(fmt::format("rank {}: {}", group->rank(), e.what()), 1);
    throw;
  }
  interrupt.watch(nullptr);
  if (group) {
    // Rank 0 receives every rank's frame entries (the chunks are in rank order, so frames stay in
    // order); once it has them, every frame file is written.
    const std::string mine = frames.dump();
    const std::vector<std::vector<uint8_t>> all = group->gather(std::vector<uint8_t>(mine.begin(), mine.end()));
    if (!root) return interrupt.signal() != 0 ? interrupt.exit_code() : 0;
    frames = nlohmann::ordered_json::array();
    for (const std::vector<uint8_t>& bytes : all)
      for (const auto& entry : nlohmann::ordered_json::parse(std::string(bytes.begin(), bytes.end()))) frames.push_back(entry);
    rendered = frames.size();
  }

  if (!o.stats_path.empty()) {
    nlohmann::ordered_json j;
    j["scene"] = prepared.display_name;
    j["integrator"] = config.integrator;
    j["filter"] = config.filter.name;
    j["width"] = width;
    j["height"] = height;
    j["fps"] = o.fps;
    j["spp_per_frame"] = spp;
    j["seed"] = config.seed;
    j["frames"] = frames;
    write_text_file(o.stats_path, j.dump(2) + "\n");
  }
  std::error_code ec;
  if (!o.video.empty() && frames.size() > 0) encode_video(ffmpeg, png_pattern, range.first, o.fps, o.video);
  if (!temporary_pngs.empty()) std::filesystem::remove_all(temporary_pngs, ec);
  if (interrupt.signal() != 0) {
    fmt::print(stderr, "pathspace render: interrupted after {} of {} frames\n", frames.size(), range.count());
    return interrupt.exit_code();
  }
  if (!quiet) fmt::print("{} frames written\n", rendered);
  return 0;
}

}  // namespace pathspace::cli
