#include "pathspace/io/atomic_file.h"

#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "pathspace/base/error.h"

namespace pathspace {

namespace fs = std::filesystem;

namespace {

// A name next to `path` that no other writer (thread or process) uses.
std::string temporary_name(const std::string& path) {
  static std::atomic<unsigned> counter{0};
  return path + ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(counter.fetch_add(1));
}

void check_parent_folder(const std::string& path) {
  const fs::path parent = fs::path(path).parent_path();
  if (parent.empty()) return;
  std::error_code ec;
  const fs::file_status st = fs::status(parent, ec);
  if (!fs::exists(st)) throw Error("cannot write '" + path + "': folder '" + parent.string() + "' does not exist");
  if (!fs::is_directory(st)) throw Error("cannot write '" + path + "': '" + parent.string() + "' is not a folder");
}

}  // namespace

void write_file_atomically(const std::string& path, const std::function<void(const std::string&)>& write) {
  if (path.empty()) throw Error("empty output file name");
  check_parent_folder(path);
  if (fs::is_directory(path)) throw Error("cannot write '" + path + "': it is a folder");
  const std::string temp = temporary_name(path);
  try {
    write(temp);
    std::error_code ec;
    fs::rename(temp, path, ec);
    if (ec) throw Error("cannot write '" + path + "': " + ec.message());
  } catch (...) {
    std::error_code ignored;
    fs::remove(temp, ignored);
    throw;
  }
}

void write_text_file(const std::string& path, const std::string& text) {
  write_file_atomically(path, [&](const std::string& temp) {
    std::ofstream out(temp, std::ios::binary | std::ios::trunc);
    if (!out) throw Error("cannot write '" + path + "': " + std::strerror(errno));
    out << text;
    out.close();
    if (!out) throw Error("cannot write '" + path + "': write failed");
  });
}

void check_output_writable(const std::string& path) {
  if (path.empty()) throw Error("empty output file name");
  check_parent_folder(path);
  if (fs::is_directory(path)) throw Error("cannot write '" + path + "': it is a folder");
  const std::string probe = temporary_name(path);
  std::ofstream out(probe, std::ios::binary);
  const int err = errno;
  if (!out) throw Error("cannot write '" + path + "': " + std::strerror(err));
  out.close();
  std::error_code ignored;
  fs::remove(probe, ignored);
}

}  // namespace pathspace
