#include "pathspace/session/run_options.h"

#include "pathspace/options/option_parse.h"
#include "pathspace/scene/scene_validation.h"

namespace pathspace {

namespace {

OptionSpec number_option(const char* name, OptionType type, const std::string& default_text, double min, double max,
                         const std::string& help) {
  OptionSpec s;
  s.name = name;
  s.type = type;
  s.default_text = default_text;
  s.min = min;
  s.max = max;
  s.help = help;
  return s;
}

// A value given as a number (Python) checked as its text would be on the command line.
void check_range(const OptionSpec& s, double value) {
  if (s.type == OptionType::integer)
    parse_integer_option(s.name, number_text(value), s.min, s.max);
  else
    parse_double_option(s.name, number_text(value), s.min, s.max);
}

}  // namespace

const std::vector<OptionSpec>& run_options() {
  static const std::string default_size = std::to_string(kDefaultImageSide) + "x" + std::to_string(kDefaultImageSide);
  static const std::vector<OptionSpec> options = {
      number_option("spp", OptionType::integer, std::to_string(kDefaultSpp), 1, double(kMaxSamplesPerPixel),
                    "Samples per pixel (default " + std::to_string(kDefaultSpp) + ", or the scene file's; with --resume: in total)"),
      number_option("time", OptionType::real, "", 1e-3, 1e7,
                    "Render for this many seconds (whole passes) instead of --spp; with --resume: this many more"),
      number_option("threads", OptionType::integer, "0", 0, 4096, "Worker threads (0: all cores)"),
      number_option("resolution", OptionType::size, default_size, 1, kMaxImageSide,
                    "Image size WxH (default " + default_size + ", or the scene file's)"),
      number_option("seed", OptionType::integer, "0", 0, double(kMaxSeed), "Random seed (renders are a pure function of the seed)"),
  };
  return options;
}

const OptionSpec& run_option(RunOption which) { return run_options()[size_t(which)]; }

RunLimit run_limit(std::optional<double> spp, std::optional<double> time, int scene_file_spp) {
  if (spp && time) throw OptionError("--spp and --time exclude each other: give one");
  if (time) {
    check_range(run_option(RunOption::time), *time);
    return RunLimit::for_seconds(*time);
  }
  if (spp) {
    check_range(run_option(RunOption::spp), *spp);
    return RunLimit::for_passes(uint32_t(*spp));
  }
  return RunLimit::for_passes(scene_file_spp > 0 ? uint32_t(scene_file_spp) : kDefaultSpp);
}

void check_threads(double threads) { check_range(run_option(RunOption::threads), threads); }

Resolution image_size(const std::string& text) {
  if (text.empty()) return Resolution{kDefaultImageSide, kDefaultImageSide};
  const OptionSpec& s = run_option(RunOption::resolution);
  return parse_resolution_option(s.name, text, int(s.max));
}

void check_image_size(int width, int height) {
  const OptionSpec& s = run_option(RunOption::resolution);
  for (const int side : {width, height}) parse_integer_option(s.name, std::to_string(side), s.min, s.max);
}

}  // namespace pathspace
