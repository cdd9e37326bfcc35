#include "pathspace/io/atomic_file.h"

#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "pathspace/base/error.h"
#include "pathspace/io/file_identity.h"

namespace pathspace {

namespace fs = std::filesystem;

namespace {

// Temporary files being written, where a signal handler can find them: fixed slots of fixed-size
// names (no allocation in the handler). A slot is claimed with `state` 0 -> 1, filled, published
// with 1 -> 2; the handler unlinks the names of published slots.
constexpr size_t kSlots = 64;
constexpr size_t kNameBytes = 4096;
struct TempSlot {
  std::atomic<int> state{0};
  char name[kNameBytes];
};
std::array<TempSlot, kSlots> g_temps;

// Lists `temp` (when it fits) for remove_unfinished_temporaries while in scope.
class ListedTemporary {
 public:
  explicit ListedTemporary(const std::string& temp) {
    if (temp.size() >= kNameBytes) return;
    for (TempSlot& s : g_temps) {
      int expected = 0;
      if (!s.state.compare_exchange_strong(expected, 1)) continue;
      std::memcpy(s.name, temp.c_str(), temp.size() + 1);
      s.state.store(2);
      slot_ = &s;
      return;
    }
  }
  ~ListedTemporary() {
    if (slot_) slot_->state.store(0);
  }
  ListedTemporary(const ListedTemporary&) = delete;
  ListedTemporary& operator=(const ListedTemporary&) = delete;

 private:
  TempSlot* slot_ = nullptr;
};

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

void check_target(const std::string& path) {
  if (path.empty()) throw Error("empty output file name");
  check_parent_folder(path);
  std::error_code ec;
  const fs::file_status st = fs::status(path, ec);  // through a symlink: what it points to
  if (fs::is_directory(st)) throw Error("cannot write '" + path + "': it is a folder");
  // The rename that puts a finished output in place would replace a device node (/dev/null) or a
  // FIFO by a regular file: such a target is refused, before the render.
  const char* kind = fs::is_character_file(st) ? "a character device"
                     : fs::is_block_file(st)   ? "a block device"
                     : fs::is_fifo(st)         ? "a FIFO (named pipe)"
                     : fs::is_socket(st)       ? "a socket"
                                               : nullptr;
  if (kind)
    throw Error("cannot write '" + path + "': it is " + kind + "; outputs are written as regular files (leave the option out instead)");
}

void rename_into_place(const std::string& temp, const std::string& path) {
  std::error_code ec;
  fs::rename(temp, path, ec);
  if (ec) throw Error("cannot write '" + path + "': " + ec.message());
}

// Writes bytes to `file`, checking every step, and fsyncs it, so that once renamed it is never an
// empty or partial file after a crash. Errors name `shown_as` (the final path). When `replaced`
// exists, the new file takes its permission bits, as `cp` over an existing file keeps them (the
// owner stays the writer's: a rename cannot keep another user's ownership).
void write_bytes_synced(const std::string& file, const void* data, size_t size, const std::string& shown_as,
                        const std::string& replaced) {
  std::FILE* f = std::fopen(file.c_str(), "wb");
  // Errors name the output, not its temporary name (the user never gave that one).
  if (!f) throw Error("cannot write '" + shown_as + "': " + std::strerror(errno));
  int err = 0;  // first errno seen
  auto check = [&](bool ok) {
    if (!ok && err == 0) err = errno ? errno : EIO;
  };
  struct stat old {};
  if (::stat(replaced.c_str(), &old) == 0) check(::fchmod(fileno(f), old.st_mode & 07777) == 0);
  check(size == 0 || std::fwrite(data, 1, size, f) == size);
  check(std::fflush(f) == 0);
  check(fsync(fileno(f)) == 0);
  check(std::fclose(f) == 0);
  if (err != 0) throw Error("cannot write '" + shown_as + "': " + std::strerror(err));
}

}  // namespace

void write_file_atomically(const std::string& path, const void* data, size_t size) {
  OutputSet set;
  set.add(path, data, size);
  set.commit();
}

void write_text_file(const std::string& path, const std::string& text) { write_file_atomically(path, text.data(), text.size()); }

void check_output_writable(const std::string& path) {
  check_target(path);
  const std::string probe = temporary_name(path);
  std::ofstream out(probe, std::ios::binary);
  const int err = errno;
  if (!out) throw Error("cannot write '" + path + "': " + std::strerror(err));
  out.close();
  std::error_code ignored;
  fs::remove(probe, ignored);
}

struct OutputSet::Listed : ListedTemporary {
  using ListedTemporary::ListedTemporary;
};

OutputSet::OutputSet() = default;

OutputSet::~OutputSet() {
  for (size_t i = committed_; i < temps_.size(); ++i) {
    std::error_code ignored;
    fs::remove(temps_[i], ignored);
  }
}

void OutputSet::add(const std::string& path, const void* data, size_t size) {
  check_target(path);
  for (const std::string& p : paths_)
    if (same_file(p, path)) throw Error("cannot write '" + path + "' twice in one set of outputs ('" + p + "' is the same file)");
  // Through a symlink: the temporary lies next to the link's target and replaces it, the link stays.
  const std::string target = write_target(path);
  const std::string temp = temporary_name(target);
  auto listed = std::make_unique<Listed>(temp);
  try {
    write_bytes_synced(temp, data, size, path, target);
  } catch (...) {
    std::error_code ignored;
    fs::remove(temp, ignored);
    throw;
  }
  paths_.push_back(path);
  targets_.push_back(target);
  temps_.push_back(temp);
  listed_.push_back(std::move(listed));
}

void OutputSet::commit() {
  for (; committed_ < temps_.size(); ++committed_) {
    rename_into_place(temps_[committed_], targets_[committed_]);
    listed_[committed_].reset();
  }
}

void remove_unfinished_temporaries() noexcept {
  for (TempSlot& s : g_temps)
    if (s.state.load() == 2) ::unlink(s.name);
}

}  // namespace pathspace
