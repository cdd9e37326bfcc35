// The body of every libFuzzer target: load the input, and abort (a finding) when the loader fails
// with an Error that names no file. Crashes, sanitizer reports and other exceptions are findings
// by themselves.
#pragma once

#include <cstdint>
#include <cstdio>
#include <cstdlib>

#include "fuzz/fuzz_inputs.h"

namespace pathspace::fuzz {

inline int fuzz_one(Format format, const uint8_t* data, size_t size) {
  static const InputFolder folder;
  const Outcome o = load_bytes(format, std::string_view(reinterpret_cast<const char*>(data), size), folder);
  if (!o.loaded && o.location.file.empty()) {
    std::fprintf(stderr, "pathspace fuzz: Error without a location: %s\n", o.error.c_str());
    std::abort();
  }
  return 0;
}

}  // namespace pathspace::fuzz
