// The run options of every render, beside its integrator's and filter's: how long it runs (--spp
// or --time) and on how many threads. Described once, as OptionSpecs like the registry's, so that
// the CLI's render and study commands, the Python package and `pathspace info --json` take one
// default, one range and one help text from here. They do not change the image (free to change on
// --resume, apps/pathspace/render_resume.h). --seed is not among them: any 64-bit value is one,
// which a double-valued OptionSpec range cannot state exactly.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "pathspace/options/option_spec.h"
#include "pathspace/session/render_session.h"

namespace pathspace {

enum class RunOption { spp, time, threads };

// Passes of a render that names neither --spp nor --time (and whose scene file names none).
inline constexpr uint32_t kDefaultSpp = 16;

const OptionSpec& run_option(RunOption which);
// Every run option, in the order above.
const std::vector<OptionSpec>& run_options();

// The run limit of --spp or --time (at most one given; neither: the scene file's spp when it names
// one, else kDefaultSpp). Throws OptionError naming the option for a value outside its range, or
// when both are given.
RunLimit run_limit(std::optional<double> spp, std::optional<double> time, int scene_file_spp = 0);
// Throws OptionError unless `threads` is within --threads' range.
void check_threads(double threads);

}  // namespace pathspace
