// Names for parameterized tests (the 4th argument of INSTANTIATE_TEST_SUITE_P): gtest allows only
// [A-Za-z0-9_] and the names must be unique per suite; without a generator tests are numbered and
// --gtest_list_tests prints struct parameters as "N-byte object <...>".
#pragma once

#include <gtest/gtest.h>

#include <string>
#include <string_view>

namespace pathspace::testing {

// Every character outside [A-Za-z0-9_] becomes '_' ("0.5" -> "0_5", "cornell-box" -> "cornell_box").
inline std::string test_name(std::string_view s) {
  std::string out(s);
  for (char& c : out)
    if (!((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_')) c = '_';
  return out.empty() ? std::string("_") : out;
}

// Name generator for parameters that are strings (const char*, std::string): the sanitised string.
struct StringParamName {
  template <class T>
  std::string operator()(const ::testing::TestParamInfo<T>& info) const {
    return test_name(std::string_view(info.param));
  }
};

}  // namespace pathspace::testing
