// libFuzzer target: the pbrt-v4 tokenizer, parser and scene builder on a scene given as text.
// Build and run: scripts/fuzz pbrt (docs/fuzzing.md).
#include "fuzz/fuzz_target.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  return pathspace::fuzz::fuzz_one(pathspace::fuzz::Format::pbrt, data, size);
}
