// libFuzzer target: the command-line parser (argv from bytes, NUL-separated; fuzz/cli_input.h).
// Build and run: scripts/fuzz cli (docs/fuzzing.md).
#include <cstdint>

#include "fuzz/cli_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  pathspace::fuzz::parse_cli_words(pathspace::fuzz::cli_words(std::string_view(reinterpret_cast<const char*>(data), size)));
  return 0;
}
