// libFuzzer target: the glTF loader (tinygltf + io/gltf/) through load_scene; the input (JSON or GLB bytes) is written to a file.
// Build and run: scripts/fuzz gltf (docs/fuzzing.md).
#include "fuzz/fuzz_target.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  return pathspace::fuzz::fuzz_one(pathspace::fuzz::Format::gltf, data, size);
}
