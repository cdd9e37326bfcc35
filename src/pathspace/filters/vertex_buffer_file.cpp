#include "pathspace/filters/vertex_buffer_file.h"

#include <cstring>
#include <fstream>
#include <type_traits>
#include <vector>

#include "pathspace/base/error.h"
#include "pathspace/base/regular_file.h"

namespace pathspace {

namespace {

constexpr char kMagic[8] = {'P', 'S', 'V', 'B', 'U', 'F', '\r', '\n'};  // \r\n: a text-mode copy breaks it
constexpr uint32_t kVersion = 2;  // 2: record r of path p in slot r * paths + p (was p * records + r)
// A batch never has more record slots than the filter's 32-bit slot indices allow.
constexpr uint64_t kMaxSlots = uint64_t(1) << 31;

class Writer {
 public:
  explicit Writer(const std::string& path) : path_(path), out_(path, std::ios::binary | std::ios::trunc) {
    if (!out_) throw Error("cannot write the vertex buffer file " + path);
  }
  template <typename T>
  void put(const T& v) {
    out_.write(reinterpret_cast<const char*>(&v), sizeof v);
  }
  template <typename T, typename A>
  void put_array(const std::vector<T, A>& v) {
    put(uint64_t(v.size() * sizeof(T)));
    out_.write(reinterpret_cast<const char*>(v.data()), std::streamsize(v.size() * sizeof(T)));
  }
  void finish() {
    out_.flush();
    if (!out_) throw Error("writing the vertex buffer file " + path_ + " failed");
  }

 private:
  std::string path_;
  std::ofstream out_;
};

class Reader {
 public:
  explicit Reader(const std::string& path) : path_(path), in_((require_regular_file(path), path), std::ios::binary | std::ios::ate) {
    if (!in_) throw Error("cannot open the vertex buffer file " + path);
    size_ = uint64_t(in_.tellg());
    in_.seekg(0);
  }
  uint64_t remaining() { return size_ - uint64_t(in_.tellg()); }
  template <typename T>
  T get(const char* what) {
    T v;
    if (!in_.read(reinterpret_cast<char*>(&v), sizeof v)) fail(std::string("truncated in its ") + what);
    return v;
  }
  bool flag(const char* what) {
    const uint8_t b = get<uint8_t>(what);
    if (b > 1) fail(std::string("bad ") + what);
    return b != 0;
  }
  // An array of `count` elements, whose stored byte count must match.
  template <typename T, typename A>
  void get_array(std::vector<T, A>* v, uint64_t count, const char* what) {
    const uint64_t bytes = get<uint64_t>(what);
    if (bytes != count * sizeof(T))
      fail(std::string("its ") + what + " array holds " + std::to_string(bytes) + " bytes, expected " +
           std::to_string(count * sizeof(T)));
    v->resize(size_t(count));
    if (!in_.read(reinterpret_cast<char*>(v->data()), std::streamsize(bytes))) fail(std::string("truncated in its ") + what + " array");
  }
  void expect_end() {
    if (in_.peek() != std::char_traits<char>::eof()) fail("data after the last array");
  }
  [[noreturn]] void fail(const std::string& why) const { throw Error("bad vertex buffer file " + path_ + ": " + why); }

 private:
  std::string path_;
  std::ifstream in_;
  uint64_t size_ = 0;
};

// VertexBuffer's fields (filters/vertex_fields.h, in its order), each with its byte count.
#define PATHSPACE_COUNT_PATH_FIELD(T, name, what) +1
#define PATHSPACE_COUNT_SLOT_FIELD(T, name, member, what) +1
constexpr int kArrays = 0 PATHSPACE_VERTEX_PATH_FIELDS(PATHSPACE_COUNT_PATH_FIELD) PATHSPACE_VERTEX_SLOT_FIELDS(PATHSPACE_COUNT_SLOT_FIELD);
#undef PATHSPACE_COUNT_PATH_FIELD
#undef PATHSPACE_COUNT_SLOT_FIELD

}  // namespace

void write_vertex_buffer_file(const std::string& path, const VertexBufferFile& f) {
  const VertexBuffer& b = f.buffer;
  const size_t slots = b.paths() * size_t(b.records_per_path());
  if (!f.filtered.empty() && f.filtered.size() != slots)
    throw Error("write_vertex_buffer_file: the filtered values must have one entry per record slot");
  Writer w(path);
  w.put(kMagic);
  w.put(kVersion);
  w.put(uint64_t(b.paths()));
  w.put(int32_t(b.records_per_path()));
  const HashedFilterSettings& s = f.settings;
  w.put(s.key.psf_scale);
  w.put(s.key.pixel_angle);
  w.put(uint8_t(s.key.jitter));
  w.put(uint8_t(s.key.normal));
  w.put(int32_t(s.key.normal_bins));
  w.put(int32_t(s.key.direction_bins));
  w.put(s.key.glossy_roughness);
  w.put(s.table_factor);
  w.put(int32_t(s.max_probes));
  w.put(int32_t(s.min_count));
  w.put(uint8_t(s.neighbour_search));
  w.put(uint8_t(s.multi_level));
  w.put(f.pixels);
  w.put(f.seed);
  w.put(f.pass);
  w.put(uint8_t(!f.filtered.empty()));
  // Slots that hold no record are written as zeros: the buffer leaves them unwritten.
  std::vector<uint8_t> holds(slots, 0);
  for (size_t path = 0; path < b.paths(); ++path)
    for (int r = 0; r < b.count[path]; ++r) holds[b.slot(path, r)] = 1;
  const auto records_only = [&](const auto& field) {
    std::vector<typename std::decay_t<decltype(field)>::value_type> out(field.size());
    for (size_t i = 0; i < out.size(); ++i)
      if (holds[i]) out[i] = field[i];
    return out;
  };
#define PATHSPACE_PUT_PATH_FIELD(T, name, what) w.put_array(b.name);
#define PATHSPACE_PUT_SLOT_FIELD(T, name, member, what) w.put_array(records_only(b.name));
  PATHSPACE_VERTEX_PATH_FIELDS(PATHSPACE_PUT_PATH_FIELD)
  PATHSPACE_VERTEX_SLOT_FIELDS(PATHSPACE_PUT_SLOT_FIELD)
#undef PATHSPACE_PUT_PATH_FIELD
#undef PATHSPACE_PUT_SLOT_FIELD
  if (!f.filtered.empty()) w.put_array(records_only(f.filtered));
  w.finish();
}

VertexBufferFile read_vertex_buffer_file(const std::string& path) {
  Reader r(path);
  char magic[8];
  for (char& c : magic) c = r.get<char>("magic");
  if (std::memcmp(magic, kMagic, sizeof magic) != 0) r.fail("not a vertex buffer file (wrong magic)");
  const uint32_t version = r.get<uint32_t>("version");
  if (version != kVersion) r.fail("version " + std::to_string(version) + ", this program reads " + std::to_string(kVersion));
  const uint64_t paths = r.get<uint64_t>("path count");
  const int32_t records = r.get<int32_t>("records per path");
  if (records < 1 || records > kMaxPathRecords) r.fail("records per path " + std::to_string(records) + " out of range");
  if (paths > kMaxSlots / uint64_t(records)) r.fail(std::to_string(paths) + " paths: too many record slots");
  VertexBufferFile f;
  HashedFilterSettings& s = f.settings;
  s.key.psf_scale = r.get<float>("voxel scale");
  s.key.pixel_angle = r.get<float>("pixel angle");
  s.key.jitter = r.flag("jitter flag");
  const uint8_t normal = r.get<uint8_t>("normal mode");
  if (normal > uint8_t(NormalKeyMode::fingerprint)) r.fail("bad normal mode");
  s.key.normal = NormalKeyMode(normal);
  s.key.normal_bins = r.get<int32_t>("normal bins");
  s.key.direction_bins = r.get<int32_t>("direction bins");
  s.key.glossy_roughness = r.get<float>("glossy roughness");
  s.table_factor = r.get<float>("table factor");
  s.max_probes = r.get<int32_t>("probe limit");
  s.min_count = r.get<int32_t>("minimum count");
  s.neighbour_search = r.flag("neighbour flag");
  s.multi_level = r.flag("multi-level flag");
  f.pixels = r.get<uint64_t>("pixel count");
  f.seed = r.get<uint64_t>("seed");
  f.pass = r.get<uint32_t>("pass");
  const bool has_filtered = r.flag("filtered flag");
  const uint64_t slots = paths * uint64_t(records);
  // The arrays' sizes follow from the header: check them against the file before allocating.
  const uint64_t expected = paths * VertexBuffer::bytes_per_path() + slots * VertexBuffer::bytes_per_slot() +
                            (has_filtered ? slots * sizeof(Rgb) : 0) + (kArrays + (has_filtered ? 1 : 0)) * sizeof(uint64_t);
  if (r.remaining() != expected)
    r.fail("it holds " + std::to_string(r.remaining()) + " bytes of arrays, its header says " + std::to_string(expected));
  VertexBuffer& b = f.buffer;
  b.resize(size_t(paths), records);
#define PATHSPACE_GET_PATH_FIELD(T, name, what) r.get_array(&b.name, paths, what);
#define PATHSPACE_GET_SLOT_FIELD(T, name, member, what) r.get_array(&b.name, slots, what);
  PATHSPACE_VERTEX_PATH_FIELDS(PATHSPACE_GET_PATH_FIELD)
  PATHSPACE_VERTEX_SLOT_FIELDS(PATHSPACE_GET_SLOT_FIELD)
#undef PATHSPACE_GET_PATH_FIELD
#undef PATHSPACE_GET_SLOT_FIELD
  for (const uint8_t c : b.count)
    if (c > records) r.fail("a path has more records than its slots");
  if (has_filtered) r.get_array(&f.filtered, slots, "filtered");
  r.expect_end();
  return f;
}

}  // namespace pathspace
