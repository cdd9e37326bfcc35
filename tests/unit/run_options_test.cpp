// The run options (session/run_options.h): one default and one range for the CLI and Python.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "pathspace/session/run_options.h"

namespace pathspace {
namespace {

TEST(RunOptions, DefaultSppUnlessTheSceneFileNamesOne) {
  EXPECT_EQ(run_limit(std::nullopt, std::nullopt).passes, kDefaultSpp);
  EXPECT_EQ(run_limit(std::nullopt, std::nullopt, 64).passes, 64u);
  EXPECT_EQ(run_limit(8.0, std::nullopt, 64).passes, 8u);
  const RunLimit timed = run_limit(std::nullopt, 2.5, 64);
  EXPECT_EQ(timed.passes, 0u);
  EXPECT_EQ(timed.seconds, 2.5);
  EXPECT_EQ(run_option(RunOption::spp).default_text, std::to_string(kDefaultSpp));
}

TEST(RunOptions, ValuesOutsideTheSpecsRangeNameTheOption) {
  const OptionSpec& spp = run_option(RunOption::spp);
  EXPECT_NO_THROW(run_limit(spp.max, std::nullopt));
  for (const double bad : {0.0, spp.max + 1, 1.5}) {
    try {
      run_limit(bad, std::nullopt);
      ADD_FAILURE() << bad;
    } catch (const OptionError& e) {
      EXPECT_NE(std::string(e.what()).find("--spp"), std::string::npos) << e.what();
    }
  }
  EXPECT_THROW(run_limit(std::nullopt, 0.0), OptionError);
  EXPECT_THROW(run_limit(std::nullopt, run_option(RunOption::time).max * 2), OptionError);
  EXPECT_THROW(run_limit(4.0, 1.0), OptionError);
  EXPECT_NO_THROW(check_threads(0));
  EXPECT_NO_THROW(check_threads(run_option(RunOption::threads).max));
  EXPECT_THROW(check_threads(-1), OptionError);
  EXPECT_THROW(check_threads(run_option(RunOption::threads).max + 1), OptionError);
}

TEST(RunOptions, EachIsListedOnceInOrder) {
  const std::vector<OptionSpec>& all = run_options();
  ASSERT_EQ(all.size(), 5u);
  EXPECT_EQ(run_option(RunOption::spp).name, "spp");
  EXPECT_EQ(run_option(RunOption::time).name, "time");
  EXPECT_EQ(run_option(RunOption::threads).name, "threads");
  EXPECT_EQ(run_option(RunOption::resolution).name, "resolution");
  EXPECT_EQ(run_option(RunOption::seed).name, "seed");
}

TEST(RunOptions, ImageSizeHasOneDefaultAndOneRange) {
  const OptionSpec& spec = run_option(RunOption::resolution);
  EXPECT_EQ(spec.type, OptionType::size);
  const Resolution d = image_size("");
  EXPECT_EQ(d.width, kDefaultImageSide);
  EXPECT_EQ(d.height, kDefaultImageSide);
  EXPECT_EQ(spec.default_text, std::to_string(d.width) + "x" + std::to_string(d.height));
  const Resolution r = image_size("640X360");
  EXPECT_EQ(r.width, 640);
  EXPECT_EQ(r.height, 360);
  const int max = int(spec.max);
  EXPECT_NO_THROW(image_size(std::to_string(max) + "x1"));
  EXPECT_NO_THROW(check_image_size(1, max));
  for (const std::string& bad : std::vector<std::string>{"0x10", "10x" + std::to_string(max + 1), "10", "10x10x10", "-4x4"}) {
    try {
      image_size(bad);
      ADD_FAILURE() << bad;
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find("--resolution"), std::string::npos) << e.what();
    }
  }
  EXPECT_THROW(check_image_size(0, 10), OptionError);
  EXPECT_THROW(check_image_size(10, max + 1), OptionError);
}

TEST(RunOptions, EverySixtyFourBitValueIsASeed) {
  const OptionSpec& spec = run_option(RunOption::seed);
  EXPECT_EQ(spec.type, OptionType::integer);
  EXPECT_EQ(spec.default_text, "0");
  EXPECT_EQ(spec.min, 0.0);
  EXPECT_EQ(spec.max, double(kMaxSeed));
  EXPECT_EQ(kMaxSeed, UINT64_MAX);
}

}  // namespace
}  // namespace pathspace
