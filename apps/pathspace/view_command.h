// `pathspace view SCENE [render options]` (docs/viewer.md): renders progressively while a browser
// page served by the renderer shows the passes, and restarts the view when the page moves the camera.
#pragma once

#include <cstdint>
#include <string>

#include <CLI/CLI.hpp>

#include "render_command.h"

namespace pathspace::cli {

struct ViewOptions {
  RenderOptions render;  // the scene and image options of `render` (add_scene_options)
  uint16_t port = 0;     // 0: a free port
  std::string listen;    // address to bind; empty: 127.0.0.1 without a token
  uint32_t max_spp = 0;  // passes per view before the loop idles; 0: no limit
  int preview = 2;       // a moved camera's first frame at 1/preview of the resolution; 1: none
  double fps = 30.0;     // animation time per played frame: 1 / fps seconds
  std::string out_dir = "pathspace-out";  // where the page's Save writes (created when needed)
  std::string reference;  // an image to measure the render against; empty: none
};

CLI::App* add_view_command(CLI::App& app, ViewOptions* options);
// Runs until SIGINT or SIGTERM; returns 128 + the signal.
int run_view_command(const ViewOptions& options, const CLI::App& cmd);

}  // namespace pathspace::cli
