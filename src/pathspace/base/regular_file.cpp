#include "pathspace/base/regular_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "pathspace/base/error.h"
#include "pathspace/base/input_file_log.h"

namespace pathspace {

namespace {

const char* not_regular(mode_t mode) {
  if (S_ISDIR(mode)) return "is a directory, not a file";
  if (S_ISFIFO(mode)) return "is a FIFO (named pipe), not a regular file";
  if (S_ISCHR(mode)) return "is a character device, not a regular file";
  if (S_ISBLK(mode)) return "is a block device, not a regular file";
  if (S_ISSOCK(mode)) return "is a socket, not a regular file";
  return S_ISREG(mode) ? nullptr : "is not a regular file";
}

// An open descriptor of the regular file `path` (the caller closes it). O_NONBLOCK: opening a FIFO
// that has no writer would otherwise wait for one, deaf to SIGTERM; the descriptor's mode is then
// checked before anything is read.
class RegularFile {
 public:
  explicit RegularFile(const std::string& path) : path_(path) {
    fd_ = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd_ < 0) {
      const int e = errno;
      throw Error(FileLoc{path}, e == ENOENT ? std::string("file not found") : std::string("cannot open: ") + std::strerror(e));
    }
    struct stat st {};
    if (::fstat(fd_, &st) != 0) {
      const int e = errno;
      ::close(fd_);
      throw Error(FileLoc{path}, std::string("cannot open: ") + std::strerror(e));
    }
    if (const char* what = not_regular(st.st_mode)) {
      ::close(fd_);
      throw Error(FileLoc{path}, what);
    }
    size_ = uint64_t(st.st_size);
  }
  ~RegularFile() { ::close(fd_); }
  RegularFile(const RegularFile&) = delete;
  RegularFile& operator=(const RegularFile&) = delete;

  std::string read_all() const {
    std::string bytes;
    bytes.reserve(size_t(size_));
    char buffer[1 << 16];
    for (;;) {
      const ssize_t n = ::read(fd_, buffer, sizeof buffer);
      if (n < 0) {
        if (errno == EINTR) continue;
        throw Error(FileLoc{path_}, std::string("read error: ") + std::strerror(errno));
      }
      if (n == 0) break;
      bytes.append(buffer, size_t(n));
    }
    return bytes;
  }

 private:
  std::string path_;
  int fd_ = -1;
  uint64_t size_ = 0;
};

}  // namespace

std::string read_file_as_stored_unlogged(const std::string& path) { return RegularFile(path).read_all(); }

std::string read_file_as_stored(const std::string& path) {
  std::string bytes = read_file_as_stored_unlogged(path);
  InputFileLog::note(path, &bytes);
  return bytes;
}

void require_regular_file(const std::string& path) {
  { RegularFile file(path); }
  InputFileLog::note(path, nullptr);
}

}  // namespace pathspace
