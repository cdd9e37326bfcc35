// `pathspace render`: options, their validation, and the run (scene -> render -> files).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "pathspace/session/render_config.h"

#include "pathspace/io/file_bytes.h"
#include "pathspace/scene/scene.h"
#include "registry_options.h"

namespace pathspace::cli {

struct RenderOptions {
  std::string scene;  // built-in scene name or id, or a scene file (.pbrt, .ply, .obj)
  // Camera for scene files ("x,y,z"; empty: the file's camera, or framing the bounds for OBJ/PLY).
  std::string camera_pos, camera_target, camera_up;
  float fov = 0.f;  // degrees, shorter image axis; 0: the file's
  float lens_radius = -1.f;    // thin lens radius in scene units (0: pinhole); < 0: the scene's
  float focus_distance = 0.f;  // distance of the focus plane; 0: the scene's
  std::string pixel_filter;    // camera/pixel_filter_table.h names; empty: the scene's
  float pixel_filter_radius = 0.f;  // pixels; 0: the filter's usual radius (or the scene's, same kind)
  bool substitute_missing_textures = false;  // pbrt: neutral stand-ins for missing images (warnings)
  std::vector<std::string> defines;          // Mitsuba: "NAME=VALUE" scene parameters (-D)
  std::string animation;                     // glTF: the animation played (index or name); empty: the first
  std::string integrator = "pt";
  uint32_t spp = 0;        // 0: unset
  double time_s = 0.0;     // 0: unset
  std::string resolution;  // "WxH"; empty: 512x512
  uint64_t seed = 0;
  int threads = 0;
  std::string device = "cpu";  // integrators/device_registry.h
  std::vector<std::string> outputs;
  std::string stats_path;
  std::string variance_path;  // variance-of-the-mean image
  bool quiet = false;
  // Checkpoints and interruption (docs/checkpoints.md).
  std::string checkpoint;         // --checkpoint FILE: the render's state, at the end and when interrupted
  double checkpoint_every = 0.0;  // seconds between checkpoints while rendering; 0: at the end only
  std::string resume;             // --resume FILE: continue the render saved there
  double write_every = 0.0;       // seconds between output writes while rendering; 0: at the end only
  double max_decompression_ratio = kDefaultMaxDecompressionRatio;  // gzip scene files (io/file_bytes.h)
  std::string light_selection = light_selection_name(kDefaultLightSelection);
  std::string filter = "none";  // path space filter (filters/filter_registry.h)
  // Animations (render_frames.h, docs/animation.md).
  std::string frames;       // "A:B"; empty: a still image
  double fps = 30.0;        // frames per second of animation time
  float orbit = 0.f;        // degrees per frame about the scene centre
  std::string camera_path;  // keyframes file
  std::string video;        // .mp4 encoded with ffmpeg
  // The integrators' and filters' own options, from the registry.
  RegistryOptionParser registry;
};

// Adds the `render` subcommand to app; the options are stored in *options.
CLI::App* add_render_command(CLI::App& app, RenderOptions* options);
// The options that choose what is rendered (scene, integrator, filter, resolution, camera, lens,
// pixel filter, scene parameters, device, seed, light selection), shared by `render` and `view`;
// the registry's integrator and filter options are added by options->registry.add_to(cmd).
void add_scene_options(CLI::App* cmd, RenderOptions* options);
// Runs the command parsed by `cmd` (the subcommand add_render_command returned). Returns the exit
// status (0, or 128 + signal when interrupted). Throws UsageError for invalid options,
// pathspace::Error for failures.
int run_render_command(const RenderOptions& options, const CLI::App& cmd);
// The checks made before anything is loaded: the scene argument, and the integrator, filter, device
// and their options against the registry. Throws UsageError naming the option.
RenderConfig check_render_options(const RenderOptions& options, const CLI::App& cmd);

}  // namespace pathspace::cli
