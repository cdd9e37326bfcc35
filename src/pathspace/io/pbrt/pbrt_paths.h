// Where a file named in a pbrt-v4 scene is (Include, plymesh, spectrum files): an absolute name as
// it is; a relative one against the folder of the file that names it, else, when it is not there,
// against the main scene file's folder (pbrt-v4 resolves against the main file; scenes split into
// included files name their neighbours either way).
#pragma once

#include <filesystem>
#include <string>

namespace pathspace::pbrt {

inline std::filesystem::path resolve_scene_file(const std::string& name, const std::string& naming_folder,
                                                const std::string& main_folder) {
  std::filesystem::path path(name);
  if (!path.is_relative()) return path;
  std::error_code ec;
  const std::filesystem::path local = std::filesystem::path(naming_folder) / path;
  return std::filesystem::exists(local, ec) || main_folder.empty() ? local : std::filesystem::path(main_folder) / path;
}

}  // namespace pathspace::pbrt
