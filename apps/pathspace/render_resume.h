// What `pathspace render --resume FILE` checks and reuses: the options that affect the image. They
// are every option of `render` except those in the group kRunOptionsGroup (samples, time, threads,
// outputs, progress, checkpoints), which may change on resume. A checkpoint stores them twice: as
// given (so a resume need not repeat them: what the command line leaves out comes from the
// checkpoint) and in canonical form, every integrator and filter option included, which must match
// the resumed render's exactly (a difference is a usage error naming the option).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>

#include "pathspace/checkpoint/checkpoint_file.h"
#include "pathspace/session/render_config.h"

namespace pathspace::cli {

// The --help group of the options that do not affect the image.
inline constexpr const char* kRunOptionsGroup = "Run and output (may change on --resume)";

// The image-affecting options given on the parsed command line `cmd` (the scene as "scene").
std::vector<GivenOption> given_image_options(const CLI::App& cmd);

// The arguments of `render` (starting with "render") for a resume: everything given on `cmd`, then
// the checkpoint's given image options that `cmd` does not give.
std::vector<std::string> resume_arguments(const CLI::App& cmd, const std::vector<GivenOption>& from_checkpoint);

// Every image-affecting option in canonical form: the scene (a built-in's name or the file's hash),
// the command's own options as given (numbers normalised; "" when not given), and every option of
// the integrator and filter in `config` with its value.
std::vector<std::pair<std::string, std::string>> canonical_image_options(const CLI::App& cmd, const std::string& scene_key,
                                                                         const RenderConfig& config);

// Throws UsageError naming the first option whose canonical value differs from the checkpoint's.
void check_resume_options(const CheckpointInfo& checkpoint, const std::vector<std::pair<std::string, std::string>>& now);

}  // namespace pathspace::cli
