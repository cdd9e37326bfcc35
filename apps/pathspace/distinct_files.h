// The files one command reads and writes, checked before any work: an output may not name another
// output or an input. Compared by file identity (io/file_identity.h), so "./a.exr", "a.exr", a
// symlink or a hard link to it are one file. Used by render and compare.
#pragma once

#include <string>
#include <vector>

namespace pathspace::cli {

struct NamedFile {
  std::string option;  // how the command line named it: "-o", "--stats", "image", ...
  std::string path;
};

// Throws UsageError naming both options when two outputs are one file or an output is one of the
// inputs (an input may be read twice).
void check_distinct_files(const std::vector<NamedFile>& outputs, const std::vector<NamedFile>& inputs);

}  // namespace pathspace::cli
