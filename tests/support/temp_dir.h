// A fresh directory under the system temp folder, unique to this process, removed with everything
// in it. ctest runs each test case as its own process, in parallel: tests that wrote fixed paths
// such as /tmp/pathspace_obj_test/box.obj truncated each other's files mid-read.
#pragma once

#include <filesystem>
#include <random>
#include <string>
#include <system_error>
#include <vector>
#include <algorithm>

#include <unistd.h>

namespace pathspace::testing {

struct TempDir {
  std::filesystem::path path;
  explicit TempDir(const std::string& tag = "test") {
    path = std::filesystem::temp_directory_path() /
           ("pathspace-" + tag + "-" + std::to_string(getpid()) + "-" + std::to_string(std::random_device{}()));
    std::filesystem::create_directories(path);
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  std::string file(const std::string& name) const { return (path / name).string(); }
  std::vector<std::string> entries() const {
    std::vector<std::string> names;
    for (const auto& e : std::filesystem::directory_iterator(path)) names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
  }
};

}  // namespace pathspace::testing
