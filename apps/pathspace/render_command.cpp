#include "render_command.h"

#include <algorithm>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <tuple>

#include <fmt/format.h>

#include "pathspace/accel/accel.h"
#include "pathspace/base/printable.h"
#include "pathspace/camera/pixel_filter_table.h"
#include "pathspace/checkpoint/checkpoint_file.h"
#include "pathspace/filters/filter_registry.h"
#include "pathspace/integrators/device_registry.h"
#include "pathspace/integrators/integrator_registry.h"
#include "pathspace/session/render.h"
#include "pathspace/session/render_session.h"
#include "pathspace/io/atomic_file.h"
#include "pathspace/io/image_io.h"
#include "pathspace/io/scene_loader.h"
#include "pathspace/options/option_parse.h"
#include "pathspace/options/option_spec.h"
#include "pathspace/scene/builtin_scenes.h"
#include "pathspace/scene/scene_validation.h"
#include "distinct_files.h"
#include "interrupt_handler.h"
#include "job_group.h"
#include "number_options.h"
#include "periodic_writer.h"
#include "progress_reporter.h"
#include "render_outputs.h"
#include "render_frames.h"
#include "render_resume.h"
#include "render_scene.h"
#include "pathspace/session/render_stats_json.h"
#include "pathspace/options/usage_error.h"
#include "pathspace/session/run_options.h"

namespace pathspace::cli {

namespace {

// The names of the registered filters, with "none".
std::vector<std::string> filter_choices() {
  std::vector<std::string> names = {FilterChoice::kNone};
  for (const std::string& n : filter_registry().names()) names.push_back(n);
  return names;
}

const char* signal_name(int sig) { return sig == SIGINT ? "SIGINT" : sig == SIGTERM ? "SIGTERM" : "a signal"; }

}  // namespace

void add_scene_options(CLI::App* cmd, RenderOptions* o) {
  cmd->add_option("scene", o->scene, "Built-in scene name or id (see 'pathspace info --scenes'), or a .pbrt/.xml/.gltf/.glb/.ply/.obj file")
      ->default_str(kDefaultSceneName);
  cmd->add_option("-i,--integrator", o->integrator,
                  fmt::format("Integrator: {} (see 'pathspace info --integrators')", integrator_registry().joined_names()))
      ->capture_default_str();
  cmd->add_option("--filter", o->filter, "Path space filter of the selected vertices (with an integrator that composes with it)")
      ->check(CLI::IsMember(filter_choices()))
      ->capture_default_str();
  cmd->add_option("-r,--resolution", o->resolution, run_option(RunOption::resolution).help)->type_name("WxH");
  cmd->add_option("--camera-pos", o->camera_pos, "Camera position x,y,z (any scene)");
  cmd->add_option("--camera-target", o->camera_target, "With --camera-pos: point the camera looks at x,y,z (default: the scene centre)");
  cmd->add_option("--camera-up", o->camera_up, "With --camera-pos: camera up vector x,y,z (default 0,1,0)");
  cmd->add_option("--fov", o->fov, "Field of view of the shorter image axis in degrees (any scene; a placed camera has square pixels)")->check(checked_real("fov", 0.01, 179.0));
  cmd->add_option("--lens-radius", o->lens_radius, "Thin lens radius in scene units for depth of field (0: pinhole; default: the scene's)")
      ->check(checked_real("lens-radius", 0.0, kMaxSceneCoordinate));
  cmd->add_option("--focus-distance", o->focus_distance, "Distance of the plane in focus along the view axis (default: the scene's)")
      ->check(checked_real("focus-distance", 1e-30, kMaxSceneCoordinate));
  cmd->add_option("--pixel-filter", o->pixel_filter,
                  "The film's reconstruction filter: box, tent, gaussian or mitchell (default: the scene's, else a box of one pixel)")
      ->check(CLI::IsMember(pixel_filter_names()));
  cmd->add_option("--pixel-filter-radius", o->pixel_filter_radius,
                  "Its radius in pixels (default: the scene file's, else box 0.5, tent 2, gaussian 1.5 with sigma radius/3, mitchell 2)")
      ->check(checked_real("pixel-filter-radius", 0.01, kMaxPixelFilterRadius));
  cmd->add_option("-D,--define", o->defines,
                  "Mitsuba scene files: the scene parameter NAME ($NAME in the file) is VALUE, in place of the file's <default> (repeatable)")
      ->type_name("NAME=VALUE")
      ->allow_extra_args(false)  // one value per -D (the scene may follow), every -D kept
      ->check([](const std::string& v) {
        const size_t eq = v.find('=');
        return eq == std::string::npos || eq == 0 ? std::string("expected NAME=VALUE, got '" + v + "'") : std::string();
      });
  cmd->add_option("--animation", o->animation, "glTF scene files: the animation to play, by index or name (default: the first)")
      ->type_name("N|NAME");
  cmd->add_flag("--substitute-missing-textures", o->substitute_missing_textures,
                "Scene files: replace missing image textures by mid grey 0.5 and a missing environment map by white 1 (warnings)");
  cmd->add_option("--device", o->device,
                  fmt::format("Where the passes run: {} (an integrator or filter the device does not run is a usage error; "
                              "'pathspace info' names the GPU)",
                              device_registry().joined_names()))
      ->check(CLI::IsMember(device_registry().names()))
      ->capture_default_str();
  cmd->add_option("--seed", o->seed, run_option(RunOption::seed).help)
      ->check(seed_check())
      ->capture_default_str();
  cmd->add_option("--light-selection", o->light_selection,
                  "How lights are picked: uniform, power, or bvh (light paths by power, next event estimation by the light tree)")
      ->check(CLI::IsMember(light_selection_names()))
      ->capture_default_str();
}

CLI::App* add_render_command(CLI::App& app, RenderOptions* o) {
  CLI::App* cmd = app.add_subcommand("render", "Render a scene to EXR/PFM/PNG");
  add_scene_options(cmd, o);
  // What does not change the image: free to change when a render is resumed (render_resume.h).
  // The run options' help and ranges: session/run_options.h.
  const OptionSpec& spp_spec = run_option(RunOption::spp);
  const OptionSpec& time_spec = run_option(RunOption::time);
  const OptionSpec& threads_spec = run_option(RunOption::threads);
  CLI::Option* spp = cmd->add_option("-s,--spp", o->spp, spp_spec.help)
                         ->check(checked_integer(spp_spec.name, spp_spec.min, spp_spec.max))
                         ->group(kRunOptionsGroup);
  cmd->add_option("-t,--time", o->time_s, time_spec.help)
      ->check(checked_real(time_spec.name, time_spec.min, time_spec.max))
      ->excludes(spp)
      ->group(kRunOptionsGroup);
  cmd->add_option("-j,--threads", o->threads, threads_spec.help)
      ->check(checked_integer(threads_spec.name, threads_spec.min, threads_spec.max))
      ->capture_default_str()
      ->group(kRunOptionsGroup);
  cmd->add_option("-o,--out", o->outputs, "Output file(s): .exr, .pfm or .png (default pathspace-out/SCENE.exr and .png)")->group(kRunOptionsGroup);
  cmd->add_option("--stats", o->stats_path, "Write run statistics as JSON to this file")->group(kRunOptionsGroup);
  cmd->add_option("--variance-out", o->variance_path, "Write the per-pixel variance of the mean (.exr/.pfm; .png would clamp it)")
      ->group(kRunOptionsGroup);
  cmd->add_flag("-q,--quiet", o->quiet, "No progress output")->group(kRunOptionsGroup);
  CLI::Option* checkpoint = cmd->add_option("--checkpoint", o->checkpoint,
                                            "Save the render's state to this file when it ends or is interrupted (it may name the --resume file)")
                                ->group(kRunOptionsGroup);
  cmd->add_option("--checkpoint-every", o->checkpoint_every, "Also save the checkpoint every S seconds while rendering (between passes)")
      ->check(checked_real("checkpoint-every", 1e-3, 1e9))
      ->needs(checkpoint)
      ->group(kRunOptionsGroup);
  cmd->add_option("--resume", o->resume, "Continue the render saved in this checkpoint (--spp: to N in total; --time: S more seconds)")
      ->group(kRunOptionsGroup);
  cmd->add_option("--write-every", o->write_every, "Write the outputs every S seconds while rendering (between passes)")
      ->check(checked_real("write-every", 1e-3, 1e9))
      ->group(kRunOptionsGroup);
  cmd->add_option("--max-decompression-ratio", o->max_decompression_ratio,
                  "A gzip scene file may decompress to at most this many times its size (at least 256 MiB; 0: no limit)")
      ->check(checked_real("max-decompression-ratio", 0.0, 1e9))
      ->capture_default_str()
      ->group(kRunOptionsGroup);
  const char* animation = "Animation (docs/animation.md)";
  CLI::Option* frames = cmd->add_option("--frames", o->frames, "Render frames FIRST:LAST of an animation into numbered files (-o out/frame-%04d.exr)")
                            ->group(animation);
  cmd->add_option("--fps", o->fps, "Frames per second of animation time")->check(checked_real("fps", 1e-3, 1e4))->capture_default_str()->needs(frames)->group(animation);
  cmd->add_option("--orbit", o->orbit, "Turn the camera about the scene centre by this many degrees per frame")
      ->check(checked_real("orbit", -360.0, 360.0))
      ->needs(frames)
      ->group(animation);
  cmd->add_option("--camera-path", o->camera_path, "Move the camera along the keyframes of this JSON file")->needs(frames)->group(animation);
  cmd->add_option("--video", o->video, "Also encode the frames into this video (.mp4) with ffmpeg")->needs(frames)->group(animation);
  o->registry.add_to(cmd);
  return cmd;
}

namespace {



// The render itself: `resumed` is the checkpoint being continued, or null. Under mpirun (job_group)
// every rank renders its passes and rank 0 alone prints and writes.
int render(const RenderOptions& o, const CLI::App& cmd, const Checkpoint* resumed) {
  const std::shared_ptr<ProcessGroup> group = job_group();
  const bool root = !group || group->rank() == 0;
  // Validate everything before the (possibly long) render.
  RenderConfig config;
  agreed_step(group.get(), [&] { config = check_render_options(o, cmd); });
  // How much is rendered: every rank must run the same passes and frames (-j may differ).
  require_same_on_every_rank(group.get(), "run options (-s, -t, --frames, --fps, --orbit, --camera-path)",
                             fmt::format("-s {} -t {} --frames '{}' --fps {} --orbit {} --camera-path '{}'", o.spp, o.time_s, o.frames,
                                         o.fps, o.orbit, o.camera_path));
  if (!o.frames.empty()) return render_frame_sequence(o, config);
  const bool quiet = o.quiet || !root;
  OutputPlan plan;
  std::vector<NamedFile> outputs;  // every file this render writes, the checkpoint included
  agreed_step(group.get(), [&] {
    if (resumed && o.spp == 0 && o.time_s <= 0.0)
      throw UsageError("--resume needs --spp N (samples per pixel in total) or --time S (seconds more)");
    const std::string scene_name = o.scene.empty() ? kDefaultSceneName : o.scene;
    const bool from_file = names_scene_file(scene_name);
    const BuiltinSceneInfo* builtin = from_file ? nullptr : find_builtin_scene(scene_name);
    if (!from_file && !builtin) throw UsageError("unknown scene '" + scene_name + "'", "run 'pathspace info --scenes' for the list, or pass a .pbrt/.xml/.gltf/.glb/.ply/.obj file");
    plan.images = image_output_paths(o.outputs, from_file ? std::filesystem::path(scene_name).stem().string() : std::string(builtin->name));
    plan.variance = o.variance_path;
    plan.stats = o.stats_path;
    if (!root) return;  // only rank 0 writes
    std::vector<NamedFile> files, inputs;
    for (const std::string& path : plan.images) files.push_back({"-o", path}), check_image_path("-o", path);
    if (!plan.variance.empty()) files.push_back({"--variance-out", plan.variance}), check_image_path("--variance-out", plan.variance);
    if (!plan.stats.empty()) files.push_back({"--stats", plan.stats}), check_output_writable(plan.stats);
    if (from_file) inputs.push_back({"the scene file", scene_name});
    // The new checkpoint may replace the resumed one (atomically); no other output may.
    if (!o.resume.empty()) inputs.push_back({"--resume", o.resume});
    check_distinct_files(files, inputs);
    outputs = files;
    if (!o.checkpoint.empty()) {
      check_output_writable(o.checkpoint);
      outputs.push_back({"--checkpoint", o.checkpoint});
      check_distinct_files(outputs, from_file ? std::vector<NamedFile>{inputs.front()} : std::vector<NamedFile>{});
    }
  });

  InterruptHandler interrupt(root);
  // Every rank reads the scene; one that cannot stops all of them with its message (agreed_step).
  std::optional<PreparedScene> prepared_scene;
  std::vector<std::pair<std::string, std::string>> image_options;
  std::unique_ptr<RenderSession> session_ptr;
  agreed_step(group.get(), [&] {
    prepared_scene.emplace(prepare_scene(o));
    if (root) check_distinct_files(outputs, scene_inputs(*prepared_scene));  // what the scene read, now known
    image_options = canonical_image_options(cmd, prepared_scene->key, config);
    if (resumed) check_resume_options(resumed->info, image_options);
  });
  PreparedScene& prepared = *prepared_scene;
  const int width = prepared.scene.camera.width, height = prepared.scene.camera.height;
  CheckpointInfo checkpoint_info;
  checkpoint_info.scene = prepared.label;
  checkpoint_info.scene_hash = prepared.key;
  checkpoint_info.integrator = config.integrator;
  checkpoint_info.filter = config.filter.name;
  checkpoint_info.width = width;
  checkpoint_info.height = height;
  checkpoint_info.seed = config.seed;
  checkpoint_info.options = image_options;
  checkpoint_info.given = given_image_options(cmd);
  auto checkpoint_of = [&](const RenderSession& s) {
    CheckpointInfo info = checkpoint_info;
    const RenderStats st = s.stats();
    info.passes = st.spp;
    info.seconds = st.wall_s;
    info.paths = st.paths;
    return info;
  };

  const int file_spp = prepared.file_spp;
  const std::string display_name = prepared.display_name, id = prepared.id;
  agreed_step(group.get(), [&] { session_ptr = std::make_unique<RenderSession>(std::move(prepared.scene), config); });
  RenderSession& session = *session_ptr;
  if (group) {
    // The image options and this binary must match on every rank; the session adds its options and scene.
    std::string identity = binary_identity() + " scene=" + prepared.key;
    for (const auto& [name, value] : image_options) identity += " " + name + "=" + value;
    agreed_step(group.get(), [&] { session.join(group, identity); });  // collective: every rank throws the same error
  }
  if (resumed) session.restore_state(resumed->state);
  const uint32_t done = session.passes_done();
  const uint32_t spp = o.spp > 0 ? o.spp : (file_spp > 0 ? uint32_t(file_spp) : kDefaultSpp);
  if (resumed && o.time_s <= 0.0 && spp < done)
    throw UsageError(fmt::format("--spp {}: the checkpoint holds {} samples per pixel already", spp, done),
                     "--spp is the total with --resume; give at least " + std::to_string(done));
  const uint32_t passes = resumed ? spp - done : spp;
  plan.run = RenderRunInfo{display_name, width, height, max_segments_of(o.registry.given(), session.scene()), ""};

  ProgressReporter progress(stdout, uint64_t(width) * uint64_t(height), quiet);
  if (!quiet) {
    fmt::print("pathspace: {} ({}), {}x{}, {}", display_name, id, width, height, o.integrator);
    if (group) fmt::print(", {} processes", group->size());
    if (resumed) fmt::print(", resumed from {} at {} passes", o.resume, done);
    fmt::print("\n");
  }
  // Rank 0 alone writes, and its clock decides when (PeriodicWriter).
  PeriodicWriter periodic(plan, root ? o.write_every : 0.0, root ? o.checkpoint : std::string(), root ? o.checkpoint_every : 0.0, checkpoint_of);
  interrupt.watch(&session);
  progress.watch(session);
  try {
    if (passes > 0 || o.time_s > 0.0) {
      const RunLimit limit = o.time_s > 0.0 ? RunLimit::for_seconds(o.time_s) : RunLimit::for_passes(passes);
      session.run(limit, [&](const RenderProgress& p) {
        if (!p.gathered) progress.update(p);
        periodic.after_pass(session, p.gathered);
      });
    }
  } catch (const std::exception& e) {
    // The others may be waiting in the exchange for this rank: end the job.
    if (group) abort_job(fmt::format("rank {}: {}", group->rank(), e.what()), 1);
    throw;
  }
  interrupt.watch(nullptr);
  progress.finish();
  periodic.finish();

  if (interrupt.signal() != 0 && session.passes_done() == 0) {
    if (root) fmt::print(stderr, "pathspace render: interrupted by {} before the first pass; nothing written\n", signal_name(interrupt.signal()));
    return interrupt.exit_code();
  }
  if (!root) return interrupt.signal() != 0 ? interrupt.exit_code() : 0;
  // The outputs and the checkpoint as one set: they always hold the same passes.
  const RenderSnapshot result = session.snapshot();
  ExtraOutput checkpoint;
  if (!o.checkpoint.empty()) checkpoint = {o.checkpoint, encode_checkpoint(checkpoint_of(session), session.save_state())};
  const std::vector<std::string> written =
      write_outputs(plan, result, OutputKind::final, o.checkpoint.empty() ? nullptr : &checkpoint);
  const RenderStats& stats = result.stats;
  if (interrupt.signal() != 0) {
    fmt::print(stderr, "pathspace render: interrupted by {} after {} passes ({} in this run); wrote {}\n", signal_name(interrupt.signal()),
               stats.spp, stats.spp - done, fmt::join(written, ", "));
    return interrupt.exit_code();
  }
  if (!quiet) {
    fmt::print("{} spp in {:.2f} s: {:.2f} Mrays/s, {:.3g} paths/s, {} threads", stats.spp, stats.wall_s, stats.mrays_per_s(),
               stats.paths_per_s(), stats.threads);
    if (stats.dropped_samples) fmt::print(", {} NaN/Inf samples dropped", stats.dropped_samples);
    fmt::print("\n{}{}{}wrote {}\n", format_rank_table(stats), format_statistics(stats.details), periodic.summary(), fmt::join(written, ", "));
  }
  return 0;
}

}  // namespace

namespace {
// An empty positional is a mistake (an unset shell variable), not a request for the default scene.
void check_scene_argument(const RenderOptions& o, const CLI::App& cmd) {
  if (cmd.get_option("scene")->count() > 0 && o.scene.empty())
    throw UsageError("the scene is an empty string", "run 'pathspace info --scenes' for the list, or pass a scene file");
}
}  // namespace

RenderConfig check_render_options(const RenderOptions& o, const CLI::App& cmd) {
  check_scene_argument(o, cmd);
  try {
    return configure_run(o.integrator, o.filter, o.registry.given(), o.seed, o.threads, o.device);
  } catch (const OptionError& e) {
    throw UsageError(e.what());
  }
}

int run_render_command(const RenderOptions& o, const CLI::App& cmd) {
  check_scene_argument(o, cmd);  // the rest is checked by render(), after a resume merged the checkpoint's options
  if (o.resume.empty()) return render(o, cmd, nullptr);
  const Checkpoint checkpoint = read_checkpoint(o.resume);
  // The integrator and filter first: the checkpoint's other options may not apply to another one.
  for (const auto& [option, given, then] : {std::tuple{"integrator", o.integrator, checkpoint.info.integrator},
                                            std::tuple{"filter", o.filter, checkpoint.info.filter}})
    if (cmd.get_option("--" + std::string(option))->count() > 0 && given != then)
      throw UsageError(fmt::format("--resume: --{} was '{}' in the checkpoint, this render gives '{}'", option, then, given),
                       "options that change the image cannot change on resume; leave them out to keep the checkpoint's");
  // Parse again with the checkpoint's image options filling in what this command line leaves out.
  std::vector<std::string> args = resume_arguments(cmd, checkpoint.info.given);
  CLI::App app;
  RenderOptions merged;
  CLI::App* merged_cmd = add_render_command(app, &merged);
  std::reverse(args.begin(), args.end());  // CLI11 takes a vector of arguments last first
  app.parse(args);
  return render(merged, *merged_cmd, &checkpoint);
}

}  // namespace pathspace::cli
