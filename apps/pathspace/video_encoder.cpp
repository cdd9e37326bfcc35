#include "video_encoder.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include <fmt/format.h>

#include "pathspace/base/error.h"

extern char** environ;

namespace pathspace::cli {

std::string find_ffmpeg() {
  const char* path = std::getenv("PATH");
  std::stringstream dirs(path ? path : "");
  std::string dir;
  while (std::getline(dirs, dir, ':')) {
    const std::string candidate = (dir.empty() ? std::string(".") : dir) + "/ffmpeg";
    if (::access(candidate.c_str(), X_OK) == 0) return candidate;
  }
  return {};
}

void encode_video(const std::string& ffmpeg, const std::string& png_pattern, uint64_t first, double fps, const std::string& video) {
  const std::filesystem::path target(video);
  // Same folder, so the rename is atomic; the extension tells ffmpeg the container.
  const std::string temporary = (target.parent_path() / ("." + target.stem().string() + ".tmp" + target.extension().string())).string();
  const std::string log = temporary + ".log";
  std::vector<std::string> args = {ffmpeg, "-nostdin", "-y", "-loglevel", "error", "-framerate", fmt::format("{}", fps),
                                   "-start_number", std::to_string(first), "-i", png_pattern,
                                   // yuv420p needs even sides
                                   "-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2", "-c:v", "libx264", "-pix_fmt", "yuv420p", temporary};
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  // No shell: file names reach ffmpeg as they are. Its messages go to a log read back on failure.
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  pid_t pid = 0;
  const int spawned = posix_spawn(&pid, ffmpeg.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0) throw Error("--video: cannot run " + ffmpeg + ": " + std::strerror(spawned));
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {}
  std::ifstream in(log);
  std::stringstream message;
  message << in.rdbuf();
  std::error_code ec;
  std::filesystem::remove(log, ec);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    std::filesystem::remove(temporary, ec);
    throw Error("--video: ffmpeg failed encoding " + png_pattern + ": " + message.str());
  }
  std::filesystem::rename(temporary, target);
}

}  // namespace pathspace::cli
