// `pathspace render --device`: an integrator or filter the device does not run is a usage error
// (exit 2) naming those it does; `--device cuda` without a CUDA device (or without a CUDA build) is
// an error (exit 1) saying so, and with one it renders. `info` says whether CUDA was built.
#include <unistd.h>

#include <filesystem>

#include <gtest/gtest.h>

#include "cli_process.h"
#include "pathspace/gpu/gpu_info.h"

namespace {

namespace fs = std::filesystem;
using pathspace::testing::run_pathspace;

TEST(DeviceCli, IntegratorsAndFiltersTheGpuDoesNotRunAreUsageErrors) {
  const auto bpt = run_pathspace("render cornell-box -r 8x8 -s 1 -q --device cuda -i bpt -o " + (fs::temp_directory_path() / "pathspace-device-never.pfm").string());
  EXPECT_EQ(bpt.exit_code, 2) << bpt.out;
  EXPECT_NE(bpt.out.find("--integrator bpt does not run on --device cuda yet; there: --integrator pt"), std::string::npos) << bpt.out;
  const auto consistent = run_pathspace("render cornell-box -r 8x8 -s 1 -q --device cuda --filter consistent -o " + (fs::temp_directory_path() / "pathspace-device-never.pfm").string());
  EXPECT_EQ(consistent.exit_code, 2) << consistent.out;
  EXPECT_NE(consistent.out.find("there: --filter hashed"), std::string::npos) << consistent.out;
  const auto unknown = run_pathspace("render cornell-box -r 8x8 -s 1 -q --device tpu");
  EXPECT_EQ(unknown.exit_code, 2) << unknown.out;
}

TEST(DeviceCli, CudaRendersOrSaysThereIsNoDevice) {
  const fs::path out = fs::temp_directory_path() / ("pathspace-device-" + std::to_string(::getpid()) + ".pfm");
  const auto r = run_pathspace("render cornell-box -r 16x16 -s 2 -q --device cuda -o " + out.string());
  if (pathspace::gpu::gpu_info().available) {
    EXPECT_EQ(r.exit_code, 0) << r.out;
    EXPECT_TRUE(fs::exists(out));
  } else {
    EXPECT_EQ(r.exit_code, 1) << r.out;
    EXPECT_NE(r.out.find("no CUDA device"), std::string::npos) << r.out;
    EXPECT_FALSE(fs::exists(out));
  }
  fs::remove(out);
}

TEST(DeviceCli, InfoSaysWhetherCudaWasBuilt) {
  const auto r = run_pathspace("info");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find(pathspace::gpu::gpu_info().built ? "CUDA backend: built" : "CUDA backend: not built"), std::string::npos) << r.out;
}

}  // namespace
