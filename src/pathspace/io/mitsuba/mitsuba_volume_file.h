// Mitsuba's binary grid volume files (.vol, read by its gridvolume plugin in 0.6 and 3) for the
// heterogeneous media of the Mitsuba loader: bytes 'V' 'O' 'L' 3, then little-endian int32 encoding
// (1: float32, the only one read here), int32 xres, yres, zres, int32 channels (1 or 3), six float32
// bounding box values (xmin ymin zmin xmax ymax zmax), then xres*yres*zres*channels float32 values,
// x fastest, then y, then z, channels interleaved.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace pathspace::mitsuba {

struct VolumeFile {
  uint32_t nx = 0, ny = 0, nz = 0, channels = 1;
  double bbox_min[3] = {0, 0, 0}, bbox_max[3] = {1, 1, 1};
  std::vector<float> values;
};

// Parses the bytes of the .vol file `name`. A wrong magic or version, another encoding, a channel
// count other than 1 or 3, a zero or negative resolution, a size that overflows, or a file shorter
// (truncated) or longer than its header says is a pathspace::Error naming the file.
VolumeFile parse_mitsuba_volume(const std::string& bytes, const std::string& name);
// Reads (io/file_bytes.h: regular files only, gzip allowed) and parses the file at `path`.
VolumeFile read_mitsuba_volume(const std::string& path);

}  // namespace pathspace::mitsuba
