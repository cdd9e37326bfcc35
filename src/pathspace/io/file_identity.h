// File identity for outputs: two paths name one file when they reach the same inode (a symlink, a
// hard link, "./a.exr" and "a.exr"), not when their text is equal. The CLI refuses to write one file
// twice or over an input with same_file; the atomic writer writes through symlinks with
// write_target, so replacing an output keeps the link and changes the file it points to (as cp does).
#pragma once

#include <string>

namespace pathspace {

// True when a and b name one file: for two existing files, the same device and inode; otherwise the
// same absolute path once every symlink of its existing part is resolved (weakly_canonical).
bool same_file(const std::string& a, const std::string& b);

// The file a write to `path` must replace: path itself, or the final target of the symlink chain
// it names (also when that target does not exist yet). Throws pathspace::Error on a symlink loop.
std::string write_target(const std::string& path);

}  // namespace pathspace
