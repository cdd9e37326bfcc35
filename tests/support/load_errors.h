// The scene loaders' tests: a load that must fail with an Error whose message starts with the
// input's file:line:column and names the problem.
#pragma once

#include <gtest/gtest.h>

#include <string>

#include "pathspace/base/error.h"

namespace pathspace::testing {

// Calls load(), expecting an Error whose message starts with `where` and contains `what`; `input`
// is shown when no error comes.
template <typename Load>
void expect_load_error(Load load, const std::string& where, const std::string& what, const std::string& input) {
  try {
    load();
    ADD_FAILURE() << "no error for:\n" << input;
  } catch (const Error& e) {
    const std::string m = e.what();
    EXPECT_EQ(m.rfind(where, 0), 0u) << m;
    EXPECT_NE(m.find(what), std::string::npos) << m;
  }
}

}  // namespace pathspace::testing
