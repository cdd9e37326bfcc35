// Replays the argv fuzz target's corpus (tests/fuzz/corpus/cli/, fuzz/cli_input.h) in the normal
// build: every input parses without a crash or an unexpected exception; valid_* command lines
// parse, usage_* are usage errors (exit 2 in the binary), help_* ask for help.
#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "fuzz/cli_input.h"

namespace {

namespace fs = std::filesystem;

TEST(CliFuzzCorpus, EveryInputGivesItsOutcome) {
  const fs::path folder = fs::path(PATHSPACE_SOURCE_DIR) / "tests/fuzz/corpus/cli";
  size_t files = 0;
  for (const fs::directory_entry& e : fs::directory_iterator(folder)) {
    std::ifstream in(e.path(), std::ios::binary);
    std::stringstream bytes;
    bytes << in.rdbuf();
    const std::string name = e.path().filename().string();
    const std::string outcome = pathspace::fuzz::parse_cli_words(pathspace::fuzz::cli_words(bytes.str()));
    if (name.rfind("valid_", 0) == 0) {
      EXPECT_EQ(outcome, "parsed") << name;
    } else if (name.rfind("usage_", 0) == 0) {
      EXPECT_EQ(outcome, "usage") << name;
    } else if (name.rfind("help_", 0) == 0) {
      EXPECT_EQ(outcome, "help") << name;
    }
    ++files;
  }
  EXPECT_GE(files, 10u);
}

TEST(CliFuzzCorpus, WordsSplitAtNul) {
  const std::vector<std::string> w = pathspace::fuzz::cli_words(std::string_view("render\0-s\0\0", 11));
  ASSERT_EQ(w.size(), 4u);
  EXPECT_EQ(w[0], "render");
  EXPECT_EQ(w[1], "-s");
  EXPECT_EQ(w[2], "");
  EXPECT_EQ(w[3], "");
}

}  // namespace
