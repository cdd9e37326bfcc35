// Replays every file of the fuzz seed corpus (tests/fuzz/corpus/<format>/) through the fuzzers'
// entry points in the normal build: no crash, and either a scene or a pathspace::Error that names a
// file. Files named valid_* must load and broken_* must fail; other names (crashers the fuzzers
// found, hangs, inputs that only warn) may do either.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "fuzz/fuzz_inputs.h"
#include "support/test_names.h"

namespace pathspace {
namespace fuzz {
// gtest prints the parameter in test listings (not as "4-byte object <...>"); found by ADL.
[[maybe_unused]] static void PrintTo(Format f, std::ostream* os) { *os << format_name(f); }
}  // namespace fuzz
namespace {

namespace fs = std::filesystem;
using fuzz::Format;

std::string read_bytes(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

class FuzzCorpusReplay : public ::testing::TestWithParam<Format> {};

TEST_P(FuzzCorpusReplay, EveryFileLoadsOrFailsWithLocation) {
  const Format format = GetParam();
  if (!fuzz::format_available(format)) GTEST_SKIP() << "this build has no " << fuzz::format_name(format) << " loader";
  const fs::path dir = fs::path(PATHSPACE_FUZZ_CORPUS_DIR) / fuzz::format_name(format);
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.is_regular_file()) files.push_back(e.path());
  std::sort(files.begin(), files.end());
  ASSERT_GE(files.size(), 5u) << "seed corpus missing in " << dir;
  const fuzz::InputFolder folder;
  for (const fs::path& file : files) {
    SCOPED_TRACE(file.filename().string());
    const fuzz::Outcome o = fuzz::load_bytes(format, read_bytes(file), folder);
    const std::string name = file.filename().string();
    if (!o.loaded) {
      EXPECT_FALSE(o.location.file.empty()) << "Error without a location: " << o.error;
      EXPECT_FALSE(o.error.empty());
    }
    if (name.rfind("valid_", 0) == 0) {
      EXPECT_TRUE(o.loaded) << o.error;
    }
    if (name.rfind("broken_", 0) == 0) {
      EXPECT_FALSE(o.loaded);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Formats, FuzzCorpusReplay, ::testing::Values(Format::pbrt, Format::ply, Format::obj, Format::mitsuba, Format::gltf, Format::image),
                         [](const ::testing::TestParamInfo<Format>& i) { return testing::test_name(fuzz::format_name(i.param)); });

}  // namespace
}  // namespace pathspace
