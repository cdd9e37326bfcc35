// libFuzzer target: the PLY reader (all three encodings) on raw bytes.
// Build and run: scripts/fuzz ply (docs/fuzzing.md).
#include "fuzz/fuzz_target.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  return pathspace::fuzz::fuzz_one(pathspace::fuzz::Format::ply, data, size);
}
