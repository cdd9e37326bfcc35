#include "pathspace/checkpoint/checkpoint_file.h"

#include <zlib.h>

#include <bit>
#include <cstring>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "pathspace/base/error.h"
#include "pathspace/base/fnv1a.h"
#include "pathspace/io/atomic_file.h"
#include "pathspace/io/file_bytes.h"

#ifndef PATHSPACE_VERSION
#define PATHSPACE_VERSION "unknown"
#endif

namespace pathspace {

namespace {

static_assert(std::endian::native == std::endian::little, "checkpoints are written little-endian");

constexpr char kMagic[8] = {'P', 'S', 'C', 'K', 'P', 'T', '\r', '\n'};
constexpr size_t kVersionOffset = sizeof(kMagic);
constexpr size_t kHeaderSizeOffset = kVersionOffset + sizeof(uint32_t);
constexpr size_t kHeaderOffset = kHeaderSizeOffset + sizeof(uint64_t);
constexpr size_t kChecksumBytes = sizeof(uint32_t);

using Json = nlohmann::ordered_json;

template <typename T>
T load(std::string_view bytes, size_t offset) {
  T v;
  std::memcpy(&v, bytes.data() + offset, sizeof(T));
  return v;
}

// zlib's crc32 takes at most 4 GiB at a time.
uint32_t crc32_of(const uint8_t* data, size_t size) {
  uLong crc = crc32(0L, Z_NULL, 0);
  while (size > 0) {
    const uInt chunk = uInt(std::min<size_t>(size, 1u << 30));
    crc = crc32(crc, data, chunk);
    data += chunk;
    size -= chunk;
  }
  return uint32_t(crc);
}

Json header_json(const CheckpointInfo& info) {
  Json j;
  j["format"] = "pathspace checkpoint";
  j["format_version"] = info.format_version;
  j["pathspace_version"] = info.pathspace_version;
  j["scene"] = info.scene;
  j["scene_hash"] = info.scene_hash;
  j["integrator"] = info.integrator;
  j["filter"] = info.filter;
  j["width"] = info.width;
  j["height"] = info.height;
  j["seed"] = info.seed;
  Json options = Json::object();
  for (const auto& [name, value] : info.options) options[name] = value;
  j["options"] = options;
  Json given = Json::array();
  for (const GivenOption& g : info.given) given.push_back(Json{{"name", g.name}, {"values", g.values}});
  j["given"] = given;
  j["passes"] = info.passes;
  j["seconds"] = info.seconds;
  j["paths"] = info.paths;
  return j;
}

CheckpointInfo header_info(const Json& j) {
  CheckpointInfo info;
  if (j.value("format", std::string()) != "pathspace checkpoint") throw Error("the header does not describe a pathspace checkpoint");
  info.format_version = j.at("format_version").get<uint32_t>();
  info.pathspace_version = j.at("pathspace_version").get<std::string>();
  info.scene = j.at("scene").get<std::string>();
  info.scene_hash = j.at("scene_hash").get<std::string>();
  info.integrator = j.at("integrator").get<std::string>();
  info.filter = j.at("filter").get<std::string>();
  info.width = j.at("width").get<int>();
  info.height = j.at("height").get<int>();
  info.seed = j.at("seed").get<uint64_t>();
  for (const auto& [name, value] : j.at("options").items()) info.options.emplace_back(name, value.get<std::string>());
  for (const Json& g : j.at("given")) info.given.push_back({g.at("name").get<std::string>(), g.at("values").get<std::vector<std::string>>()});
  info.passes = j.at("passes").get<uint32_t>();
  info.seconds = j.at("seconds").get<double>();
  info.paths = j.at("paths").get<uint64_t>();
  return info;
}

[[noreturn]] void bad(const std::string& path, const std::string& why) {
  throw Error(path + ": not a usable checkpoint: " + why);
}

}  // namespace

std::string checkpoint_header_json(const CheckpointInfo& info) { return header_json(info).dump(1) + "\n"; }

std::vector<uint8_t> encode_checkpoint(const CheckpointInfo& info, const SessionState& state) {
  CheckpointInfo stamped = info;
  stamped.format_version = kCheckpointFormatVersion;
  stamped.pathspace_version = PATHSPACE_VERSION;
  const std::string header = checkpoint_header_json(stamped);
  std::vector<uint8_t> out(kHeaderOffset + header.size() + sizeof(uint64_t) + state.bytes.size() + kChecksumBytes);
  size_t at = 0;
  auto put = [&](const void* data, size_t size) {
    if (size) std::memcpy(out.data() + at, data, size);
    at += size;
  };
  const uint32_t version = kCheckpointFormatVersion;
  const uint64_t header_size = header.size(), state_size = state.bytes.size();
  put(kMagic, sizeof(kMagic));
  put(&version, sizeof(version));
  put(&header_size, sizeof(header_size));
  put(header.data(), header.size());
  put(&state_size, sizeof(state_size));
  put(state.bytes.data(), state.bytes.size());
  const uint32_t crc = crc32_of(out.data(), at);
  put(&crc, sizeof(crc));
  return out;
}

Checkpoint decode_checkpoint(std::string_view bytes, const std::string& path) {
  if (bytes.size() < sizeof(kMagic) || std::memcmp(bytes.data(), kMagic, sizeof(kMagic)) != 0)
    bad(path, "it does not start like a pathspace checkpoint");
  if (bytes.size() < kHeaderOffset) bad(path, fmt::format("truncated ({} bytes)", bytes.size()));
  const uint32_t version = load<uint32_t>(bytes, kVersionOffset);
  if (version != kCheckpointFormatVersion)
    bad(path, fmt::format("it has format version {}, this pathspace ({}) reads version {}", version, PATHSPACE_VERSION, kCheckpointFormatVersion));
  const uint64_t header_size = load<uint64_t>(bytes, kHeaderSizeOffset);
  const uint64_t after_header = uint64_t(bytes.size()) - kHeaderOffset;
  if (header_size > after_header || after_header - header_size < sizeof(uint64_t))
    bad(path, fmt::format("truncated ({} bytes; the header alone claims {})", bytes.size(), header_size));
  const size_t state_size_offset = kHeaderOffset + size_t(header_size);
  const uint64_t state_size = load<uint64_t>(bytes, state_size_offset);
  const size_t state_offset = state_size_offset + sizeof(uint64_t);
  const uint64_t rest = uint64_t(bytes.size()) - state_offset;
  if (rest < kChecksumBytes || state_size > rest - kChecksumBytes)
    bad(path, fmt::format("truncated ({} bytes, {} expected)", bytes.size(),
                     state_size > rest ? std::string("more") : std::to_string(state_offset + state_size + kChecksumBytes)));
  const size_t checksum_offset = state_offset + size_t(state_size);
  if (checksum_offset + kChecksumBytes != bytes.size())
    bad(path, fmt::format("{} bytes of unexpected data after the checksum", bytes.size() - checksum_offset - kChecksumBytes));
  const uint32_t stored = load<uint32_t>(bytes, checksum_offset);
  const uint32_t computed = crc32_of(reinterpret_cast<const uint8_t*>(bytes.data()), checksum_offset);
  if (stored != computed) bad(path, fmt::format("damaged: checksum {:08x}, the content gives {:08x}", stored, computed));
  Checkpoint c;
  try {
    c.info = header_info(Json::parse(bytes.substr(kHeaderOffset, size_t(header_size))));
  } catch (const Json::exception& e) {
    bad(path, std::string("unreadable header: ") + e.what());
  } catch (const Error& e) {
    bad(path, e.what());
  }
  if (c.info.format_version != version) bad(path, "the header's format version does not match the file's");
  const auto* state = reinterpret_cast<const uint8_t*>(bytes.data()) + state_offset;
  c.state.bytes.assign(state, state + state_size);
  return c;
}

void write_checkpoint(const std::string& path, const CheckpointInfo& info, const SessionState& state) {
  const std::vector<uint8_t> bytes = encode_checkpoint(info, state);
  write_file_atomically(path, bytes.data(), bytes.size());
}

Checkpoint read_checkpoint(const std::string& path) { return decode_checkpoint(read_file_as_stored(path), path); }

std::string scene_file_hash(const std::string& path) {
  const std::string bytes = read_file_as_stored(path);
  return fmt::format("fnv1a64:{:016x}", fnv1a64(bytes.data(), bytes.size()));
}

std::string scene_files_hash(const std::vector<InputFile>& files) {
  if (files.empty()) throw Error("scene_files_hash: no files");
  uint64_t hash = files.front().fnv1a64;
  for (size_t i = 1; i < files.size(); ++i) hash = fnv1a64(&files[i].fnv1a64, sizeof(uint64_t), hash);
  return fmt::format("fnv1a64:{:016x}", hash);
}

}  // namespace pathspace
