// Reading whole input files into memory for the scene parsers (PLY, pbrt, OBJ) and the images,
// checkpoints and hashes. Gzip files are
// recognised by their magic bytes (not the name), so "mesh.ply.gz" and a gzip file without the
// suffix both work. Failures are pathspace::Error naming the file.
#pragma once

#include <cstdint>
#include <string>

#include "pathspace/base/regular_file.h"  // read_file_as_stored, require_regular_file

namespace pathspace {

// The file's bytes, gunzipped when the file starts with the gzip magic (1f 8b), without a leading
// UTF-8 byte-order mark. A gzip file may
// not decompress to more than the decompression limit below (an Error naming the file and the
// limit), so a small file of blanks cannot take gigabytes of memory.
std::string read_file_bytes(const std::string& path);

// The decompression limit, one policy for the process: a gzip file may decompress to at most
// max(floor_bytes, ratio x its compressed size); ratio 0 means no limit. Defaults: ratio 100 and a
// floor of 256 MiB (real scene text and meshes compress 2-20x; an 8.7 MB file of blanks grows
// 240x). `render --max-decompression-ratio` sets the ratio.
inline constexpr double kDefaultMaxDecompressionRatio = 100.0;
inline constexpr uint64_t kDefaultDecompressionFloorBytes = uint64_t(256) << 20;
void set_decompression_limit(double ratio, uint64_t floor_bytes = kDefaultDecompressionFloorBytes);

// Lower-case extension without the ".gz" suffix: "a/b.PLY.gz" -> ".ply".
std::string scene_file_extension(const std::string& path);

}  // namespace pathspace
