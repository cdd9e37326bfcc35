// Test data outside the repository (the Bitterli scenes; see
// docs/testing.md, "Test data outside the repository"). A test that needs it fails when it is
// missing, so that a checkout without it cannot pass silently; PATHSPACE_ALLOW_MISSING_SHARED_DATA=1
// turns the failure into a skip (same message).
//
//   PATHSPACE_REQUIRE_SHARED_DATA(path);  // in a TEST body, fixture SetUp or other void function
#pragma once

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

namespace pathspace::testing {

inline bool missing_shared_data_allowed() {
  const char* v = std::getenv("PATHSPACE_ALLOW_MISSING_SHARED_DATA");
  return v != nullptr && std::string(v) == "1";
}

// Empty when `path` exists; otherwise the failure (or skip) message.
inline std::string missing_shared_data(const std::string& path) {
  if (std::filesystem::exists(path)) return {};
  return "shared test data missing: " + path +
         " (see docs/testing.md, 'Test data outside the repository'; set PATHSPACE_ALLOW_MISSING_SHARED_DATA=1 to skip)";
}

}  // namespace pathspace::testing

// Fails the current test (skips it with PATHSPACE_ALLOW_MISSING_SHARED_DATA=1) and returns when
// `path` does not exist.
#define PATHSPACE_REQUIRE_SHARED_DATA(path)                                                            \
  do {                                                                                                 \
    const std::string pathspace_missing_ = ::pathspace::testing::missing_shared_data(path);            \
    if (!pathspace_missing_.empty()) {                                                                 \
      if (::pathspace::testing::missing_shared_data_allowed()) GTEST_SKIP() << pathspace_missing_;     \
      FAIL() << pathspace_missing_;                                                                    \
    }                                                                                                  \
  } while (0)
