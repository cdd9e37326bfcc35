// Every number on the command line goes through the checked parsers of options/option_parse.h
// (whole text, range, overflow, NaN and infinity, naming the option): as CLI11 validators for the
// typed options (WxH: options/resolution_option.h). CLI11's own conversion would wrap "-1" into a
// huge unsigned value and accept "nan" inside a Range, so it only ever sees text checked here.
#pragma once

#include <cstdint>
#include <string>

#include <CLI/CLI.hpp>

#include "pathspace/options/resolution_option.h"

namespace pathspace::cli {

// Validators for option --name (without dashes): the text must be a whole number in [min, max], a
// whole number in [0, max] for 64-bit unsigned fields, or a finite real in [min, max]. A bad value
// is a usage error (exit 2) "--name 'text': problem".
CLI::Validator checked_integer(const std::string& name, double min, double max);
CLI::Validator checked_unsigned(const std::string& name, uint64_t max);
CLI::Validator checked_real(const std::string& name, double min, double max);
// The run options that every render and study command takes, with their ranges from
// session/run_options.h.
CLI::Validator threads_check();
CLI::Validator seed_check();

}  // namespace pathspace::cli
