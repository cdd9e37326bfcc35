#include "number_options.h"

#include <functional>

#include "pathspace/options/option_parse.h"
#include "pathspace/options/option_spec.h"
#include "pathspace/session/run_options.h"

namespace pathspace::cli {

namespace {

// An OptionError becomes a CLI11 parse error carrying the message as it is: CLI11 would prefix the
// text a validator returns with the option's name, which the message already starts with.
CLI::Validator checked(const std::string& description, std::function<void(const std::string&)> parse) {
  return CLI::Validator(
      [parse = std::move(parse)](std::string& text) {
        try {
          parse(text);
        } catch (const OptionError& e) {
          throw CLI::ParseError(e.what(), CLI::ExitCodes::ValidationError);
        }
        return std::string();
      },
      description);
}

}  // namespace

CLI::Validator checked_integer(const std::string& name, double min, double max) {
  return checked("INT in [" + number_text(min) + " - " + number_text(max) + "]",
                 [=](const std::string& t) { parse_integer_option(name, t, min, max); });
}

CLI::Validator checked_unsigned(const std::string& name, uint64_t max) {
  return checked("UINT in [0 - " + std::to_string(max) + "]", [=](const std::string& t) { parse_unsigned_option(name, t, max); });
}

CLI::Validator checked_real(const std::string& name, double min, double max) {
  return checked("FLOAT in [" + number_text(min) + " - " + number_text(max) + "]",
                 [=](const std::string& t) { parse_double_option(name, t, min, max); });
}

CLI::Validator threads_check() {
  const OptionSpec& s = run_option(RunOption::threads);
  return checked_integer(s.name, s.min, s.max);
}

CLI::Validator seed_check() { return checked_unsigned(run_option(RunOption::seed).name, kMaxSeed); }

}  // namespace pathspace::cli
