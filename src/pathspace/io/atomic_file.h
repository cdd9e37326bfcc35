// Atomic file output: every file pathspace writes (images, stats JSON) is first written to a
// temporary name in the target's folder and then renamed into place, so an interrupted or failed
// run never leaves a half-written file behind (rename within one file system is atomic on POSIX).
#pragma once

#include <functional>
#include <string>

namespace pathspace {

// Calls write(temp_path), then renames temp_path to path. If write throws, or the rename fails, the
// temporary file is removed and a pathspace::Error naming `path` is thrown.
void write_file_atomically(const std::string& path, const std::function<void(const std::string& temp_path)>& write);

// Writes text to path atomically.
void write_text_file(const std::string& path, const std::string& text);

// Throws pathspace::Error when a file cannot be created next to `path` (missing folder, no
// permission, parent is not a folder). Used to fail before a long render, not after it.
void check_output_writable(const std::string& path);

}  // namespace pathspace
