// The robustness tests' fixture: a temporary folder, scene snippets, and `expect`, which runs the
// real binary there and checks its exit status, its message and that no file but the outputs changed.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "cli/cli_process.h"
#include "support/temp_dir.h"

namespace pathspace::testing {

namespace fs = std::filesystem;

// What a file is: its bytes, permission bits, and a symlink's target.
inline std::map<std::string, std::string> snapshot(const fs::path& dir) {
  std::map<std::string, std::string> files;
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    const std::string name = fs::relative(e.path(), dir).string();
    if (e.is_symlink()) files[name] = "link:" + fs::read_symlink(e.path()).string();
    else if (e.is_regular_file()) files[name] = read_all(e.path()) + "|mode:" + std::to_string(int(e.status().permissions()));
    else files[name] = "folder";
  }
  return files;
}

inline const char* kCamera =
    "LookAt 0 0 5  0 0 0  0 1 0\nCamera \"perspective\" \"float fov\" [ 40 ]\n"
    "Film \"rgb\" \"integer xresolution\" 8 \"integer yresolution\" 8\nWorldBegin\n";
inline const char* kLight = "LightSource \"point\" \"rgb I\" [ 5 5 5 ] \"point3 from\" [ 0 0 4 ]\n";

class Robustness : public ::testing::Test {
 protected:
  TempDir dir{"robustness"};

  std::string write(const std::string& name, const std::string& bytes) {
    std::ofstream(dir.file(name), std::ios::binary) << bytes;
    return name;
  }
  // Runs `pathspace ARGS` in the test folder; expects the status, every text in `names` in the
  // output, and the folder unchanged except for `outputs`.
  testing::Run expect(const std::string& args, int status, const std::vector<std::string>& names, const std::set<std::string>& outputs = {}) {
    const auto before = snapshot(dir.path);
    const fs::path cwd = fs::current_path();
    fs::current_path(dir.path);
    const testing::Run r = run_pathspace(args);
    fs::current_path(cwd);
    EXPECT_EQ(r.exit_code, status) << args << "\n" << r.out;
    for (const std::string& n : names) EXPECT_NE(r.out.find(n), std::string::npos) << args << ": no '" << n << "' in\n" << r.out;
    auto after = snapshot(dir.path);
    for (const std::string& o : outputs) after.erase(o);
    auto expected = before;
    for (const std::string& o : outputs) expected.erase(o);
    EXPECT_EQ(after, expected) << args << ": a file other than the outputs changed";
    return r;
  }
};

inline constexpr const char* kQuick = " -r 8x8 -s 1 -q";

}  // namespace pathspace::testing
