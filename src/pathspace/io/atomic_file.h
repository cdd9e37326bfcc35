// Atomic file output: every file pathspace writes (images, stats JSON, checkpoints) is first written
// to a temporary name in the target's folder and then renamed into place, so an interrupted or failed
// run never leaves a half-written file behind (rename within one file system is atomic on POSIX).
// Temporary names are NAME.tmp-PID-N; while one is being written it is listed where a signal handler
// can remove it (remove_unfinished_temporaries), so a render killed by a second Ctrl-C leaves none.
#pragma once

#include <memory>
#include <string>
#include <vector>

namespace pathspace {

// Writes the bytes to a temporary file next to `path` (fsync'd), then renames it to `path`: a set of
// one file (OutputSet below). On any failure the temporary file is removed and a pathspace::Error
// naming `path` is thrown.
void write_file_atomically(const std::string& path, const void* data, size_t size);

// Writes text to path atomically.
void write_text_file(const std::string& path, const std::string& text);

// Throws pathspace::Error when a file cannot be created next to `path` (missing folder, no
// permission, parent is not a folder). Used to fail before a long render, not after it.
void check_output_writable(const std::string& path);

// Files that replace their previous versions as one set: add() writes each file completely under its
// temporary name (nothing visible changes); commit() then renames them into place one after another.
// Until commit() the folder holds the previous set; after it, the new one. A process that dies
// between two of commit()'s renames (a few microseconds) leaves the files renamed so far new and the
// rest old, and may leave NAME.tmp-PID-N files; no file is ever partial. A set destroyed without
// commit() removes its temporaries. A path that is a symlink replaces the link's target (the link
// stays); a replaced file's permission bits are kept. Two paths naming one file (io/file_identity.h)
// are an error.
class OutputSet {
 public:
  OutputSet();
  ~OutputSet();
  OutputSet(const OutputSet&) = delete;
  OutputSet& operator=(const OutputSet&) = delete;

  void add(const std::string& path, const void* data, size_t size);
  void add(const std::string& path, const std::string& bytes) { add(path, bytes.data(), bytes.size()); }
  // Renames every added file into place in the order added. Throws pathspace::Error naming the file
  // whose rename failed (the others are left as they are then).
  void commit();
  const std::vector<std::string>& paths() const { return paths_; }

 private:
  struct Listed;  // a temporary listed for remove_unfinished_temporaries until renamed or removed
  std::vector<std::string> paths_, targets_, temps_;  // as given, after symlinks, temporary
  std::vector<std::unique_ptr<Listed>> listed_;
  size_t committed_ = 0;  // files renamed so far
};

// Async-signal-safe: removes the temporary files being written right now (write_file_atomically and
// OutputSet). For a signal handler that ends the process at once (pathspace render, second Ctrl-C).
void remove_unfinished_temporaries() noexcept;

}  // namespace pathspace
