// `pathspace render SCENE --frames A:B`: renders frames A to B of an animation in order with one
// session, so that the hashed filter's table carries across them (--temporal; 2021 paper sec. 3.4).
// The camera moves by --orbit or --camera-path, animated built-in scenes move their lights and
// objects; each frame is written to numbered files (-o out/frame-%04d.exr), --stats gets one entry
// per frame and --video encodes the sequence with ffmpeg (docs/animation.md).
#pragma once

#include "pathspace/session/render_config.h"
#include "render_command.h"

namespace pathspace::cli {

// Returns the exit status (0, or 128 + signal when interrupted). Throws UsageError for options that
// do not apply to frame sequences, pathspace::Error for failures.
int render_frame_sequence(const RenderOptions& options, const RenderConfig& config);

}  // namespace pathspace::cli
