// The run options of every render, beside its integrator's and filter's: how long it runs (--spp
// or --time), on how many threads, the image size (-r) and the seed. Described once, as OptionSpecs
// like the registry's, so that the CLI's render and study commands, the Python package and
// `pathspace info --json` take one default, one range and one help text from here. The first three
// do not change the image (free to change on --resume, apps/pathspace/render_resume.h); the image
// size and the seed do.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "pathspace/options/option_spec.h"
#include "pathspace/options/resolution_option.h"
#include "pathspace/session/render_session.h"

namespace pathspace {

enum class RunOption { spp, time, threads, resolution, seed };

// Passes of a render that names neither --spp nor --time (and whose scene file names none).
inline constexpr uint32_t kDefaultSpp = 16;
// The image of a render that names no -r (and whose scene file names no size): square, this wide.
inline constexpr int kDefaultImageSide = 512;
// Every 64-bit value is a seed (the spec's double-valued max only states it to the reader).
inline constexpr uint64_t kMaxSeed = UINT64_MAX;

const OptionSpec& run_option(RunOption which);
// Every run option, in the order above.
const std::vector<OptionSpec>& run_options();

// The run limit of --spp or --time (at most one given; neither: the scene file's spp when it names
// one, else kDefaultSpp). Throws OptionError naming the option for a value outside its range, or
// when both are given.
RunLimit run_limit(std::optional<double> spp, std::optional<double> time, int scene_file_spp = 0);
// Throws OptionError unless `threads` is within --threads' range.
void check_threads(double threads);
// The image size of -r "WxH" (empty: kDefaultImageSide square). Throws UsageError naming
// --resolution for a malformed size or a side out of range.
Resolution image_size(const std::string& text);
// Throws OptionError naming --resolution unless both sides are within its range.
void check_image_size(int width, int height);

}  // namespace pathspace
