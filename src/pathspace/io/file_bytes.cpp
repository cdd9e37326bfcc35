// Whole-file reads with transparent gzip decompression through zlib (see file_bytes.h).
#include "pathspace/io/file_bytes.h"

#include <fmt/format.h>
#include <zlib.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <filesystem>

#include "pathspace/base/error.h"

namespace pathspace {

namespace {

struct DecompressionLimit {
  std::atomic<double> ratio{kDefaultMaxDecompressionRatio};
  std::atomic<uint64_t> floor_bytes{kDefaultDecompressionFloorBytes};
};
DecompressionLimit& decompression_limit() {
  static DecompressionLimit limit;
  return limit;
}

std::string gunzip(const std::string& path, uint64_t compressed_size) {
  const double ratio = decompression_limit().ratio.load();
  const uint64_t floor_bytes = decompression_limit().floor_bytes.load();
  const double scaled = ratio * double(compressed_size);
  const uint64_t limit = ratio <= 0.0 ? UINT64_MAX : std::max<uint64_t>(floor_bytes, scaled >= 1.8e19 ? UINT64_MAX : uint64_t(scaled));
  gzFile f = gzopen(path.c_str(), "rb");
  if (!f) throw Error(FileLoc{path}, "cannot open gzip file");
  std::string out;
  char buffer[1 << 16];
  for (;;) {
    const int n = gzread(f, buffer, sizeof buffer);
    if (n < 0) {
      int code = 0;
      const std::string message = gzerror(f, &code);
      gzclose(f);
      throw Error(FileLoc{path}, "corrupt gzip data: " + message);
    }
    if (n == 0) break;
    if (out.size() + size_t(n) > limit) {
      gzclose(f);
      throw Error(FileLoc{path}, fmt::format("decompresses to more than {:.1f} MiB, over {:g}x its {:.1f} MiB (raise or lift the limit "
                                             "with --max-decompression-ratio; 0: no limit)",
                                             double(limit) / 1048576.0, ratio, double(compressed_size) / 1048576.0));
    }
    out.append(buffer, size_t(n));
  }
  // gzread returns 0 at a truncated stream too; gzclose reports it as Z_BUF_ERROR.
  if (gzclose(f) != Z_OK) throw Error(FileLoc{path}, "truncated gzip data");
  return out;
}

}  // namespace

std::string read_file_bytes(const std::string& path) {
  std::string bytes = read_file_as_stored(path);
  if (bytes.size() >= 2 && uint8_t(bytes[0]) == 0x1f && uint8_t(bytes[1]) == 0x8b) bytes = gunzip(path, bytes.size());
  // A UTF-8 byte-order mark (editors on Windows write one) is not the file's first statement; without
  // it, columns in messages count as editors show them.
  if (bytes.compare(0, 3, "\xEF\xBB\xBF") == 0) bytes.erase(0, 3);
  return bytes;
}

void set_decompression_limit(double ratio, uint64_t floor_bytes) {
  decompression_limit().ratio = ratio;
  decompression_limit().floor_bytes = floor_bytes;
}


std::string scene_file_extension(const std::string& path) {
  std::filesystem::path p(path);
  std::string ext = p.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  if (ext == ".gz") {
    ext = p.stem().extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  }
  return ext;
}

}  // namespace pathspace
