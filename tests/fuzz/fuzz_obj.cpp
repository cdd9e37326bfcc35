// libFuzzer target: the OBJ/MTL loader (tinyobjloader + obj_loader.cpp) through load_scene; the input is written to a file.
// Build and run: scripts/fuzz obj (docs/fuzzing.md).
#include "fuzz/fuzz_target.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  return pathspace::fuzz::fuzz_one(pathspace::fuzz::Format::obj, data, size);
}
