#include "pathspace/session/run_options.h"

#include "pathspace/options/option_parse.h"

namespace pathspace {

namespace {

OptionSpec number_option(const char* name, OptionType type, const char* default_text, double min, double max, const char* help) {
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
  static const std::vector<OptionSpec> options = {
      number_option("spp", OptionType::integer, "16", 1, double(1 << 24),
                    "Samples per pixel (default 16, or the scene file's; with --resume: in total)"),
      number_option("time", OptionType::real, "", 1e-3, 1e7,
                    "Render for this many seconds (whole passes) instead of --spp; with --resume: this many more"),
      number_option("threads", OptionType::integer, "0", 0, 4096, "Worker threads (0: all cores)"),
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

}  // namespace pathspace
