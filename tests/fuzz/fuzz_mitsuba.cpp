// libFuzzer target: the Mitsuba XML loader on a scene given as text.
// Build and run: scripts/fuzz mitsuba (docs/fuzzing.md).
#include "fuzz/fuzz_target.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  return pathspace::fuzz::fuzz_one(pathspace::fuzz::Format::mitsuba, data, size);
}
