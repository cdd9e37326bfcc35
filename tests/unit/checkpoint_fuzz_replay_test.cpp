// Replays the checkpoint fuzz corpus (tests/fuzz/corpus/checkpoint/) through the fuzz target's entry
// point (fuzz/checkpoint_input.h) in the normal build and, with the scene parsers' corpus, under
// ASan/UBSan (scripts/test-sanitizers): valid_* files (checkpoints and bare session states of the
// reference sessions) must restore, broken_* files must fail with pathspace::Error; other names
// (findings of the fuzzer) may do either, but nothing may crash or throw anything else.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "fuzz/checkpoint_input.h"
#include "pathspace/base/error.h"

namespace pathspace {
namespace {

namespace fs = std::filesystem;

TEST(FuzzCorpusCheckpoint, EveryFileRestoresOrFailsWithError) {
  const fs::path dir = fs::path(PATHSPACE_FUZZ_CORPUS_DIR) / "checkpoint";
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.is_regular_file()) files.push_back(e.path());
  std::sort(files.begin(), files.end());
  ASSERT_GE(files.size(), 14u) << "seed corpus missing in " << dir;
  int valid = 0;
  for (const fs::path& file : files) {
    SCOPED_TRACE(file.filename().string());
    std::ifstream in(file, std::ios::binary);
    std::ostringstream ss;
    ss << in.rdbuf();
    bool restored = false;
    std::string error;
    try {
      restored = fuzz::restore_checkpoint_bytes(ss.str());
    } catch (const Error& e) {
      error = e.what();
    }
    const std::string name = file.filename().string();
    if (name.rfind("valid_", 0) == 0) {
      EXPECT_TRUE(restored) << error << " (after a change of the state format, regenerate the corpus: docs/testing.md)";
      ++valid;
    }
    if (name.rfind("broken_", 0) == 0) {
      EXPECT_FALSE(restored);
      EXPECT_FALSE(error.empty());
    }
  }
  EXPECT_EQ(valid, 16) << "a checkpoint and a bare state for each of the eight reference sessions";
}

}  // namespace
}  // namespace pathspace
