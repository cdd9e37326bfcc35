// libFuzzer target: the image readers (EXR through OpenEXR, PFM, and what stb reads: PNG, HDR,
// TGA, JPG, BMP) on raw bytes; the first byte picks the file name (fuzz_inputs.h).
// Build and run: scripts/fuzz image (docs/fuzzing.md).
#include "fuzz/fuzz_target.h"

#include "pathspace/io/image_io.h"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  pathspace::set_max_image_pixels(uint64_t(1) << 22);  // fast inputs; the limit's own check stays reachable
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  return pathspace::fuzz::fuzz_one(pathspace::fuzz::Format::image, data, size);
}
