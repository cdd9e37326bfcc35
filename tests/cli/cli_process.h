// Running the pathspace binary from a test and reading files: shared by the CLI tests.
#pragma once

#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace pathspace::testing {

struct Run {
  int exit_code = -1;
  std::string out;  // stdout and stderr together
};

// `pathspace ARGS` (PATHSPACE_BINARY) in the current folder.
inline Run run_pathspace(const std::string& args) {
  const std::string cmd = "'" PATHSPACE_BINARY "' " + args + " 2>&1";
  Run r;
  FILE* p = popen(cmd.c_str(), "r");
  if (!p) return r;
  char buf[4096];
  for (size_t n; (n = fread(buf, 1, sizeof buf, p)) > 0;) r.out.append(buf, n);
  const int status = pclose(p);
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

inline std::string read_all(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

}  // namespace pathspace::testing
