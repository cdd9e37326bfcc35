#include "view_command.h"

#include <algorithm>
#include <cstdio>
#include <memory>
#include <filesystem>
#include <random>

#include <nlohmann/json.hpp>

#include <fmt/format.h>
#include <fmt/printf.h>

#include "pathspace/accel/accel.h"
#include "pathspace/io/image_io.h"
#include "pathspace/session/render_session.h"
#include "distinct_files.h"
#include "video_encoder.h"
#include "pathspace/options/usage_error.h"
#include "interrupt_handler.h"
#include "number_options.h"
#include "render_scene.h"
#include "scene_animation.h"
#include "viewer/live_view.h"
#include "viewer/viewer_server.h"

namespace pathspace::cli {

namespace {

// Checks that `outputs` (the page's files) replace no input and creates their folder; an Error to the
// client otherwise.
void prepare_outputs(const std::string& folder, const std::vector<NamedFile>& outputs, const std::vector<NamedFile>& inputs) {
  try {
    check_distinct_files(outputs, inputs);
    std::filesystem::create_directories(folder);
  } catch (const std::exception& e) {
    throw Error(e.what());
  }
}

// The page's Save: NAME-LABEL.exr (as rendered) and .png (display exposure) in `folder`, written
// atomically and never over a file the scene read.
viewer::FrameSaver frame_saver(const std::string& folder, const std::string& name, std::vector<NamedFile> inputs) {
  return [=](const Image& image, const viewer::Display& display, const std::string& label) {
    const std::string base = (std::filesystem::path(folder) / (name + "-" + label)).string();
    const std::vector<NamedFile> outputs = {{"save", base + ".exr"}, {"save", base + ".png"}};
    prepare_outputs(folder, outputs, inputs);
    write_image(outputs[0].path, image);
    write_image(outputs[1].path, viewer::displayed(image, display));
    return nlohmann::json{{"saved", {outputs[0].path, outputs[1].path}}}.dump();
  };
}

// The page's recording of a flight: NAME-flight-K-%04d.png in `folder` for every frame shown, and on
// stop NAME-flight-K.mp4 at the rate the frames came (ffmpeg, as `render --video`), when ffmpeg is
// there. Its calls are serialised by LiveView.
viewer::FlightRecorder flight_recorder(const std::string& folder, const std::string& name, std::vector<NamedFile> inputs) {
  struct State {
    bool active = false;
    int flight = 0;
    uint64_t frames = 0;
    std::string pattern, video;
    std::chrono::steady_clock::time_point start;
  };
  auto state = std::make_shared<State>();
  viewer::FlightRecorder r;
  r.start = [=] {
    const int flight = state->flight + 1;
    const std::string base = (std::filesystem::path(folder) / fmt::format("{}-flight-{}", name, flight)).string();
    prepare_outputs(folder, {{"record", base + "-0000.png"}, {"record", base + ".mp4"}}, inputs);
    *state = State{true, flight, 0, base + "-%04d.png", base + ".mp4", std::chrono::steady_clock::now()};
    return nlohmann::json{{"recording", state->pattern}}.dump();
  };
  r.frame = [=](const Image& image, const viewer::Display& display) {
    if (!state->active) return;
    write_image(fmt::sprintf(state->pattern, state->frames++), viewer::displayed(image, display));
  };
  r.stop = [=] {
    state->active = false;
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - state->start).count();
    nlohmann::json reply = {{"recorded", state->frames}, {"frames", state->pattern}, {"video", nullptr}};
    const std::string ffmpeg = find_ffmpeg();
    if (state->frames >= 2 && !ffmpeg.empty()) {
      encode_video(ffmpeg, state->pattern, 0, std::clamp(double(state->frames) / std::max(seconds, 1e-3), 1.0, 120.0), state->video);
      reply["video"] = state->video;
    }
    return reply.dump();
  };
  return r;
}

// `scene` seen at 1/scale of its resolution in each axis, the same field of view.
std::shared_ptr<const Scene> preview_scene(const Scene& scene, int scale) {
  auto small = std::make_shared<Scene>(scene);
  small->camera.width = std::max(1, scene.camera.width / scale);
  small->camera.height = std::max(1, scene.camera.height / scale);
  return small;
}

// 128 random bits as hex: the token a viewer bound beyond the loopback demands.
std::string random_token() {
  std::random_device device;
  std::string token;
  for (int i = 0; i < 4; ++i) token += fmt::format("{:08x}", device());
  return token;
}

}  // namespace

CLI::App* add_view_command(CLI::App& app, ViewOptions* o) {
  CLI::App* cmd = app.add_subcommand("view", "Render progressively and watch it live in a browser (camera from the keyboard)");
  add_scene_options(cmd, &o->render);
  cmd->add_option("--port", o->port, "TCP port of the page (default: a free one)")->check(CLI::Range(0, 65535));
  cmd->add_option("--listen", o->listen,
                  "Address to bind instead of 127.0.0.1 (e.g. 0.0.0.0); then the page needs the random token in the printed URL");
  cmd->add_option("--max-spp", o->max_spp, "Passes per view, after which the viewer idles until the camera moves (default: no limit)")
      ->check(checked_integer("max-spp", 0, 1 << 24));
  cmd->add_option("--reference", o->reference,
                  "An image of the render's size (.exr, .pfm, ...) to measure it against live: relMSE, block relMSE, FLIP, error map");
  cmd->add_option("--preview", o->preview,
                  "Show each new view of a moving camera first at 1/N of the resolution (one pass, scaled up); 1: off")
      ->capture_default_str()
      ->check(checked_integer("preview", 1, 16));
  cmd->add_option("--fps", o->fps, "Animated scenes: frames per second of animation time while the page plays it (a frame after each pass)")
      ->check(checked_real("fps", 1e-3, 1e4))
      ->capture_default_str();
  cmd->add_option("--out-dir", o->out_dir, "Folder of the images the page saves (created when needed)")->capture_default_str();
  cmd->add_option("-j,--threads", o->render.threads, "Worker threads; 0 = all cores")->check(checked_integer("threads", 0, 4096));
  o->render.registry.add_to(cmd);
  return cmd;
}

int run_view_command(const ViewOptions& o, const CLI::App& cmd) {
  const RenderConfig config = check_render_options(o.render, cmd);
  std::shared_ptr<const Image> reference;
  if (!o.reference.empty()) reference = std::make_shared<const Image>(read_image(o.reference));
  PreparedScene prepared = prepare_scene(o.render);
  const std::function<Scene(double)> scene_at = scene_animation(o.render, prepared);
  auto first = std::make_shared<Scene>(prepared.scene);
  first->camera_moves = false;  // the page moves the camera
  auto accel = std::make_shared<const Accel>(*first);
  std::shared_ptr<const Scene> scene = first;  // the current view's: the first one with the page's camera
  const PerspectiveCamera home = first->camera;
  const Bounds3 bounds = first->geometry_bounds();
  const float step = bounds.empty() ? 0.1f : 0.02f * length(bounds.hi - bounds.lo);
  if (reference && (reference->width != home.width || reference->height != home.height))
    throw UsageError(fmt::format("--reference {} is {}x{}, the render {}x{}", o.reference, reference->width, reference->height, home.width,
                                 home.height),
                     "give -r the reference's size");

  std::vector<NamedFile> saved_inputs = scene_inputs(prepared);  // Save never writes over these
  if (!o.reference.empty()) saved_inputs.push_back({"--reference", o.reference});
  auto session = std::make_unique<RenderSession>(scene, accel, config);
  auto live = std::make_shared<viewer::LiveView>(
      home, step, viewer::RenderChoice{o.render.integrator, o.render.filter, o.render.registry.given(), config.seed, config.threads, config.device},
      frame_saver(o.out_dir, prepared.display_name, saved_inputs), reference,
      flight_recorder(o.out_dir, prepared.display_name, saved_inputs), scene_at ? o.fps : 0.0);
  live->set_sessions({session.get()});
  const std::string address = o.listen.empty() ? "127.0.0.1" : o.listen;
  viewer::ViewerServer server(live, address, o.port, o.listen.empty() ? "" : random_token());
  fmt::print("pathspace view: {} ({}x{}, {}): open {}\n", prepared.display_name, home.width, home.height, config.integrator, server.url());
  fmt::print("  from another machine: ssh -L {0}:localhost:{0} HOST, then http://localhost:{0}/ here; Ctrl-C ends\n", server.port());
  std::fflush(stdout);

  InterruptHandler interrupt(true, "\npathspace view: interrupted: finishing the pass in flight, then stopping\n");
  interrupt.watch(session.get());
  uint64_t view = 0;
  std::unique_ptr<RenderSession> right;    // the split screen's right half, or null
  std::unique_ptr<RenderSession> preview;  // the view at 1/--preview of the resolution, made at the first move
  while (interrupt.signal() == 0) {
    const std::optional<PerspectiveCamera> camera = live->take_camera();
    const std::optional<double> seconds = live->take_time();
    if (seconds) {  // the scene at another time, seen by the page's camera
      first = std::make_shared<Scene>(scene_at(*seconds));
      first->camera_moves = false;
      first->camera = live->camera();
      scene = first;
    } else if (camera) {
      auto moved = std::make_shared<Scene>(*first);
      moved->camera = *camera;
      scene = moved;
    }
    // At a new time the sessions build the acceleration structure (validated, the part that does not
    // move reused, accel/accel.h); the view's is then shared with the others.
    const std::shared_ptr<const Accel> frame_accel = seconds ? nullptr : accel;
    std::optional<RenderConfig> changed = live->take_config();
    // A move is answered by a preview first, before the full view restarts: one pass at a fraction
    // of the pixels; while the camera moves, the only frames shown (the next move aborts the full
    // view's pass).
    if (camera && !seconds && !changed && preview && !right) {
      preview->begin_frame(preview_scene(*scene, o.preview), accel, view + 1);
      if (preview->run(RunLimit::for_passes(1)).passes > 0) {
        RenderSnapshot shown = preview->snapshot(SnapshotImages::mean);
        viewer::LiveView::scale_up(&shown, home.width, home.height);
        live->publish(std::move(shown), view + 1, o.preview);
      }
    }
    // New sessions are handed to the page (LiveView::set_sessions) before the ones they replace go.
    std::unique_ptr<RenderSession> next_session, next_right;
    std::optional<std::optional<RenderConfig>> split = live->take_split();
    if (changed) {
      // New options: a new session on the same scene and acceleration structure; an error only the
      // session finds (a device that is not there) goes to the page, the old session goes on.
      try {
        next_session = std::make_unique<RenderSession>(scene, frame_accel, std::move(*changed));
        live->config_applied();
        preview.reset();  // made again with the new options after the view's first pass
        ++view;
      } catch (const Error& e) {
        live->config_failed(e.what());
      }
    }
    if (!next_session && (camera || seconds || session->aborted())) {
      session->begin_frame(scene, frame_accel, ++view);  // a temporal filter keeps its table (2021 paper sec. 3.4)
    }
    if (seconds) accel = (next_session ? next_session : session)->shared_accel();
    if (split && *split) {
      try {
        next_right = std::make_unique<RenderSession>(scene, accel, std::move(**split));
      } catch (const Error& e) {
        live->split_failed(e.what());
      }
    } else if (right && !split && (camera || seconds || right->aborted())) {
      right->begin_frame(scene, accel, view);
    }
    if (next_session || split) {
      RenderSession* left = next_session ? next_session.get() : session.get();
      RenderSession* other = split ? next_right.get() : right.get();
      live->set_sessions(other ? std::vector<RenderSession*>{left, other} : std::vector<RenderSession*>{left});
      if (next_session) {
        interrupt.watch(next_session.get());
        session = std::move(next_session);
      }
      if (split) right = std::move(next_right);
    }
    const auto shown = [&] {
      RenderSnapshot left = session->snapshot(SnapshotImages::mean);
      if (right) viewer::LiveView::compose_split(&left, right->snapshot(SnapshotImages::mean));
      return left;
    };
    if (o.max_spp > 0 && session->passes_done() >= o.max_spp) {
      if (live->wait_for_change(std::chrono::milliseconds(100))) live->publish(shown(), view);  // a new exposure
      continue;
    }
    const RunResult r = session->run(RunLimit::for_passes(1));
    if (right && r.passes > 0) right->run(RunLimit::for_passes(1));
    if (r.passes > 0 && !(right && right->aborted())) {
      live->publish(shown(), view);
      if (o.max_spp == 0 || session->passes_done() >= o.max_spp) live->advance_if_playing();  // a played frame is done
    }
    // Made, with a first pass, after the view's first pass, not at the move it serves: a new
    // session's first pass takes a few hundred ms more than the next (the filter's table and buffers).
    if (!preview && o.preview > 1 && r.passes > 0) {
      preview = std::make_unique<RenderSession>(preview_scene(*scene, o.preview), accel, session->config());
      preview->run(RunLimit::for_passes(1));
    }
  }
  return interrupt.exit_code();
}

}  // namespace pathspace::cli
