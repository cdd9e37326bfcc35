// Mitsuba .vol files (see mitsuba_volume_file.h). Every size is checked before it is used: the
// header's resolution decides how many bytes must follow, so a hostile header cannot make the
// reader allocate more than the file holds.
#include "pathspace/io/mitsuba/mitsuba_volume_file.h"

#include <cstring>

#include "pathspace/base/error.h"
#include "pathspace/io/file_bytes.h"

namespace pathspace::mitsuba {

namespace {

constexpr size_t kHeaderBytes = 48;  // magic 3, version 1, encoding 4, resolution 12, channels 4, bbox 24

// Little-endian, whatever the host's order (Mitsuba writes the x86 order).
uint32_t u32_at(const std::string& b, size_t at) {
  return uint32_t(uint8_t(b[at])) | uint32_t(uint8_t(b[at + 1])) << 8 | uint32_t(uint8_t(b[at + 2])) << 16 |
         uint32_t(uint8_t(b[at + 3])) << 24;
}
int32_t i32_at(const std::string& b, size_t at) {
  const uint32_t u = u32_at(b, at);
  int32_t i;
  std::memcpy(&i, &u, 4);
  return i;
}
float f32_at(const std::string& b, size_t at) {
  const uint32_t u = u32_at(b, at);
  float f;
  std::memcpy(&f, &u, 4);
  return f;
}

}  // namespace

VolumeFile parse_mitsuba_volume(const std::string& bytes, const std::string& name) {
  auto fail = [&](const std::string& what) { return Error(name + ": Mitsuba volume file: " + what); };
  if (bytes.size() < 4 || bytes.compare(0, 3, "VOL") != 0) throw fail("not a .vol file (it does not start with 'VOL')");
  if (uint8_t(bytes[3]) != 3) throw fail("version " + std::to_string(int(uint8_t(bytes[3]))) + " is not supported (only 3)");
  if (bytes.size() < kHeaderBytes)
    throw fail("truncated: " + std::to_string(bytes.size()) + " bytes, shorter than the " + std::to_string(kHeaderBytes) + "-byte header");
  const int32_t encoding = i32_at(bytes, 4);
  if (encoding != 1)
    throw fail("encoding " + std::to_string(encoding) + " is not supported (only 1, float32; 2 is float16, 3 uint8)");
  VolumeFile v;
  const int32_t res[3] = {i32_at(bytes, 8), i32_at(bytes, 12), i32_at(bytes, 16)};
  const int32_t channels = i32_at(bytes, 20);
  for (int a = 0; a < 3; ++a)
    if (res[a] < 1) throw fail("resolution " + std::to_string(res[0]) + " x " + std::to_string(res[1]) + " x " + std::to_string(res[2]) + " has an axis < 1");
  if (channels != 1 && channels != 3) throw fail(std::to_string(channels) + " channels (only 1 or 3 are read)");
  // The value count, checked against what the file can hold before each product (count * r > room
  // exactly when count > room / r), so it never overflows.
  const uint64_t room = (bytes.size() - kHeaderBytes) / 4;
  uint64_t count = uint64_t(channels);
  bool fits = count <= room;
  for (int a = 0; a < 3 && fits; ++a) {
    fits = count <= room / uint64_t(res[a]);
    if (fits) count *= uint64_t(res[a]);
  }
  if (!fits)
    throw fail("truncated: " + std::to_string(res[0]) + " x " + std::to_string(res[1]) + " x " + std::to_string(res[2]) + " x " +
               std::to_string(channels) + " values do not fit in its " + std::to_string(bytes.size()) + " bytes");
  const uint64_t expected = kHeaderBytes + count * 4;
  if (bytes.size() != expected)
    throw fail(std::to_string(bytes.size()) + " bytes where its header asks for " + std::to_string(expected));
  v.nx = uint32_t(res[0]), v.ny = uint32_t(res[1]), v.nz = uint32_t(res[2]), v.channels = uint32_t(channels);
  for (int a = 0; a < 3; ++a) {
    v.bbox_min[a] = f32_at(bytes, 24 + 4 * size_t(a));
    v.bbox_max[a] = f32_at(bytes, 36 + 4 * size_t(a));
  }
  v.values.resize(size_t(count));
  for (size_t i = 0; i < v.values.size(); ++i) v.values[i] = f32_at(bytes, kHeaderBytes + 4 * i);
  return v;
}

VolumeFile read_mitsuba_volume(const std::string& path) { return parse_mitsuba_volume(read_file_bytes(path), path); }

}  // namespace pathspace::mitsuba
