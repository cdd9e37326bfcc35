// libFuzzer target: the checkpoint reader (file container and session state) on bytes.
// Build and run: scripts/fuzz checkpoint (docs/fuzzing.md).
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "fuzz/checkpoint_input.h"
#include "pathspace/base/error.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    pathspace::fuzz::restore_checkpoint_bytes(std::string_view(reinterpret_cast<const char*>(data), size));
  } catch (const pathspace::Error&) {
    // The expected outcome for damaged input; other exceptions escape and are findings.
  }
  return 0;
}
