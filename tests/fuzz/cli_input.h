// The argv fuzz target's input: bytes split at NUL into command-line words (at most 48, each at
// most 512 bytes), after "pathspace". parse_cli_words parses them into a CliApp and, for `render`,
// runs the checks made before anything is loaded (check_render_options); nothing is rendered,
// read or written. Usage errors of every kind are expected outcomes; any other exception, a crash
// or a sanitizer report is a finding. Used by fuzz_cli.cpp and replayed by cli/cli_fuzz_replay_test.cpp.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace pathspace::fuzz {

std::vector<std::string> cli_words(std::string_view bytes);

// "usage" (a usage error, exit 2 in the binary), "parsed" (the command line is valid) or "help".
std::string parse_cli_words(const std::vector<std::string>& words);

}  // namespace pathspace::fuzz
