// libFuzzer target: the message decoder of `pathspace view` (apps/pathspace/viewer/viewer_protocol.h).
// Every input parses into a command or throws pathspace::Error; nothing else may escape.
// Build and run: scripts/fuzz viewer (docs/fuzzing.md).
#include <cstdint>
#include <string>

#include "pathspace/base/error.h"
#include "viewer/viewer_protocol.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    pathspace::viewer::parse_command(std::string(reinterpret_cast<const char*>(data), size));
  } catch (const pathspace::Error&) {
  }
  return 0;
}
