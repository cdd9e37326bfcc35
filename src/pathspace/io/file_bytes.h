// Reading whole input files into memory for the scene parsers (PLY, pbrt, OBJ). Gzip files are
// recognised by their magic bytes (not the name), so "mesh.ply.gz" and a gzip file without the
// suffix both work. Failures are pathspace::Error naming the file.
#pragma once

#include <string>

namespace pathspace {

// The file's bytes, gunzipped when the file starts with the gzip magic (1f 8b).
std::string read_file_bytes(const std::string& path);

// The file's bytes as stored (images, checkpoints, content hashes). Errors: "PATH: cannot open: ...".
std::string read_file_as_stored(const std::string& path);

// Lower-case extension without the ".gz" suffix: "a/b.PLY.gz" -> ".ply".
std::string scene_file_extension(const std::string& path);

}  // namespace pathspace
