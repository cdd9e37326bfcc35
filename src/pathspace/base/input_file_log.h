// Which files a piece of work read: while an InputFileLog lives, every file that passes the one
// input check (base/regular_file.h) is listed in it, with a fingerprint of its bytes. A render uses
// it to keep its outputs off every file the scene read (an Include, an OBJ's MTL, a texture, an
// environment map) and to fingerprint the whole scene for --resume, not only the main file.
// Process-wide (loaders read textures on worker threads); logs may nest, each sees every read.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace pathspace {

struct InputFile {
  std::string path;   // as the reader named it
  uint64_t fnv1a64;   // of the bytes as stored (base/fnv1a.h)
};

class InputFileLog {
 public:
  InputFileLog();
  ~InputFileLog();
  InputFileLog(const InputFileLog&) = delete;
  InputFileLog& operator=(const InputFileLog&) = delete;

  // The files read so far, each path once, in the order first read.
  std::vector<InputFile> files() const;

  // Called by the input check for every file read (or, for a stream reader, opened: `bytes` null).
  // A file only opened is fingerprinted when files() is asked, unless a read of it comes first: a
  // scene file is checked before its reader reads it, and is read once.
  static void note(const std::string& path, const std::string* bytes);

 private:
  struct Entry {
    std::string path;
    std::optional<uint64_t> fnv1a64;  // none yet: only opened so far
  };
  void add(const std::string& path, std::optional<uint64_t> hash);
  std::vector<Entry> entries_;
};

}  // namespace pathspace
