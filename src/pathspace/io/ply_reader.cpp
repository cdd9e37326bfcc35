// PLY parsing (see ply_reader.h). The header is parsed into element/property descriptions; the body
// is then read through one value source (ascii tokens or binary scalars of either byte order), so
// the skipping of unknown elements and the bounds checks are written once.
#include "pathspace/io/ply_reader.h"

#include <bit>
#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstring>

#include "pathspace/base/error.h"
#include "pathspace/io/file_bytes.h"

namespace pathspace {

namespace {

enum class Format { ascii, binary_le, binary_be };
enum class Scalar { i8, u8, i16, u16, i32, u32, f32, f64 };

struct Property {
  std::string name;
  Scalar type = Scalar::f32;
  bool is_list = false;
  Scalar count_type = Scalar::u8;
};

struct Element {
  std::string name;
  uint64_t count = 0;
  std::vector<Property> properties;
};

size_t scalar_size(Scalar s) {
  switch (s) {
    case Scalar::i8: case Scalar::u8: return 1;
    case Scalar::i16: case Scalar::u16: return 2;
    case Scalar::i32: case Scalar::u32: case Scalar::f32: return 4;
    case Scalar::f64: return 8;
  }
  return 1;
}

bool is_integer(Scalar s) { return s != Scalar::f32 && s != Scalar::f64; }

// Whether an ascii value fits the declared integer type (binary values fit by construction).
bool fits(Scalar s, double v) {
  switch (s) {
    case Scalar::i8: return v >= -128.0 && v <= 127.0;
    case Scalar::u8: return v >= 0.0 && v <= 255.0;
    case Scalar::i16: return v >= -32768.0 && v <= 32767.0;
    case Scalar::u16: return v >= 0.0 && v <= 65535.0;
    case Scalar::i32: return v >= -2147483648.0 && v <= 2147483647.0;
    case Scalar::u32: return v >= 0.0 && v <= 4294967295.0;
    case Scalar::f32: case Scalar::f64: return true;
  }
  return true;
}

// Both the classic names (uchar, int, float) and the sized ones (uint8, int32, float32).
bool parse_scalar(const std::string& t, Scalar* s) {
  static const std::pair<const char*, Scalar> names[] = {
      {"char", Scalar::i8},    {"int8", Scalar::i8},    {"uchar", Scalar::u8},    {"uint8", Scalar::u8},
      {"short", Scalar::i16},  {"int16", Scalar::i16},  {"ushort", Scalar::u16},  {"uint16", Scalar::u16},
      {"int", Scalar::i32},    {"int32", Scalar::i32},  {"uint", Scalar::u32},    {"uint32", Scalar::u32},
      {"float", Scalar::f32},  {"float32", Scalar::f32}, {"double", Scalar::f64}, {"float64", Scalar::f64}};
  for (const auto& [name, value] : names)
    if (t == name) {
      *s = value;
      return true;
    }
  return false;
}

std::vector<std::string> split_words(const std::string& line) {
  std::vector<std::string> words;
  size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
    size_t j = i;
    while (j < line.size() && line[j] != ' ' && line[j] != '\t' && line[j] != '\r') ++j;
    if (j > i) words.push_back(line.substr(i, j - i));
    i = j;
  }
  return words;
}

// Values of the body, one at a time, in file order.
class BodyReader {
 public:
  BodyReader(const std::string& bytes, size_t offset, Format format, const std::string& name, int first_line)
      : bytes_(bytes), pos_(offset), format_(format), name_(name), line_(first_line) {}

  double read(Scalar type) {
    if (format_ == Format::ascii) return read_ascii(type);
    const size_t n = scalar_size(type);
    if (pos_ + n > bytes_.size()) fail("unexpected end of data (file truncated)");
    unsigned char b[8];
    std::memcpy(b, bytes_.data() + pos_, n);
    const bool swap = (format_ == Format::binary_be) == (std::endian::native == std::endian::little);
    if (swap)
      for (size_t i = 0; i < n / 2; ++i) std::swap(b[i], b[n - 1 - i]);
    pos_ += n;
    switch (type) {
      case Scalar::i8: { int8_t v; std::memcpy(&v, b, 1); return v; }
      case Scalar::u8: return b[0];
      case Scalar::i16: { int16_t v; std::memcpy(&v, b, 2); return v; }
      case Scalar::u16: { uint16_t v; std::memcpy(&v, b, 2); return v; }
      case Scalar::i32: { int32_t v; std::memcpy(&v, b, 4); return v; }
      case Scalar::u32: { uint32_t v; std::memcpy(&v, b, 4); return v; }
      case Scalar::f32: { float v; std::memcpy(&v, b, 4); return v; }
      case Scalar::f64: { double v; std::memcpy(&v, b, 8); return v; }
    }
    return 0.0;
  }

  // Cheap upper bound used to reject absurd element counts before allocating.
  size_t remaining() const { return bytes_.size() - pos_; }
  void set_context(const std::string& element, uint64_t index) {
    element_ = element;
    index_ = index;
  }
  [[noreturn]] void fail(const std::string& what) const {
    std::string where = format_ == Format::ascii ? "line " + std::to_string(line_) : "byte offset " + std::to_string(pos_);
    throw Error(FileLoc{name_, format_ == Format::ascii ? line_ : 0, 0},
                what + " (" + where + ", element '" + element_ + "' #" + std::to_string(index_) + ")");
  }

 private:
  double read_ascii(Scalar type) {
    while (pos_ < bytes_.size() && std::isspace(static_cast<unsigned char>(bytes_[pos_]))) {
      if (bytes_[pos_] == '\n') ++line_;
      ++pos_;
    }
    if (pos_ >= bytes_.size()) fail("unexpected end of data (file truncated)");
    const char* begin = bytes_.data() + pos_;
    const char* end = bytes_.data() + bytes_.size();
    const char* stop = begin;
    while (stop < end && !std::isspace(static_cast<unsigned char>(*stop))) ++stop;
    double v = 0.0;
    const char* number = (*begin == '+') ? begin + 1 : begin;
    const auto r = std::from_chars(number, stop, v);
    if (r.ec != std::errc() || r.ptr != stop) fail("'" + std::string(begin, stop) + "' is not a number");
    if (is_integer(type) && v != std::floor(v)) fail("'" + std::string(begin, stop) + "' is not an integer");
    // Out-of-range integers would reach integer conversions (undefined behaviour; a fuzzer find).
    if (!fits(type, v)) fail("'" + std::string(begin, stop) + "' is out of range for its integer type");
    pos_ = size_t(stop - bytes_.data());
    return v;
  }

  const std::string& bytes_;
  size_t pos_;
  Format format_;
  const std::string& name_;
  int line_;
  std::string element_;
  uint64_t index_ = 0;
};

struct Header {
  Format format = Format::ascii;
  std::vector<Element> elements;
  size_t body_offset = 0;
  int body_line = 0;
};

Header parse_header(const std::string& bytes, const std::string& name) {
  Header h;
  size_t pos = 0;
  int line_no = 0;
  bool has_format = false;
  auto next_line = [&](std::string* line) {
    if (pos >= bytes.size()) return false;
    size_t end = bytes.find('\n', pos);
    if (end == std::string::npos) end = bytes.size();
    *line = bytes.substr(pos, end - pos);
    if (!line->empty() && line->back() == '\r') line->pop_back();
    pos = end + 1;
    ++line_no;
    return true;
  };
  std::string line;
  if (!next_line(&line) || line != "ply") throw Error(FileLoc{name, 1, 1}, "not a PLY file (first line must be 'ply')");
  for (;;) {
    if (!next_line(&line)) throw Error(FileLoc{name, line_no, 0}, "header ends without 'end_header'");
    const FileLoc loc{name, line_no, 1};
    const std::vector<std::string> w = split_words(line);
    if (w.empty() || w[0] == "comment" || w[0] == "obj_info") continue;
    if (w[0] == "end_header") break;
    if (w[0] == "format") {
      if (w.size() != 3) throw Error(loc, "expected 'format <type> 1.0'");
      if (w[1] == "ascii") h.format = Format::ascii;
      else if (w[1] == "binary_little_endian") h.format = Format::binary_le;
      else if (w[1] == "binary_big_endian") h.format = Format::binary_be;
      else throw Error(loc, "unknown PLY format '" + w[1] + "'");
      has_format = true;
    } else if (w[0] == "element") {
      if (w.size() != 3) throw Error(loc, "expected 'element <name> <count>'");
      Element e;
      e.name = w[1];
      const auto r = std::from_chars(w[2].data(), w[2].data() + w[2].size(), e.count);
      if (r.ec != std::errc() || r.ptr != w[2].data() + w[2].size()) throw Error(loc, "bad element count '" + w[2] + "'");
      h.elements.push_back(e);
    } else if (w[0] == "property") {
      if (h.elements.empty()) throw Error(loc, "property before any element");
      Property p;
      if (w.size() == 5 && w[1] == "list") {
        p.is_list = true;
        if (!parse_scalar(w[2], &p.count_type)) throw Error(loc, "unknown property type '" + w[2] + "'");
        if (!parse_scalar(w[3], &p.type)) throw Error(loc, "unknown property type '" + w[3] + "'");
        if (!is_integer(p.count_type)) throw Error(loc, "list count type must be an integer type");
        p.name = w[4];
      } else if (w.size() == 3) {
        if (!parse_scalar(w[1], &p.type)) throw Error(loc, "unknown property type '" + w[1] + "'");
        p.name = w[2];
      } else {
        throw Error(loc, "expected 'property <type> <name>' or 'property list <count type> <type> <name>'");
      }
      h.elements.back().properties.push_back(p);
    } else {
      throw Error(loc, "unknown header keyword '" + w[0] + "'");
    }
  }
  if (!has_format) throw Error(FileLoc{name, line_no, 0}, "header has no 'format' line");
  h.body_offset = pos;
  h.body_line = line_no + 1;
  return h;
}

// Where each vertex attribute comes from (property index, or -1).
struct VertexLayout {
  int slot[8];  // x y z nx ny nz u v
  VertexLayout() { std::fill(std::begin(slot), std::end(slot), -1); }
};

VertexLayout vertex_layout(const Element& e) {
  static const char* const names[8][3] = {{"x"}, {"y"}, {"z"}, {"nx"}, {"ny"}, {"nz"},
                                          {"u", "s", "texture_u"}, {"v", "t", "texture_v"}};
  VertexLayout l;
  for (size_t i = 0; i < e.properties.size(); ++i) {
    if (e.properties[i].is_list) continue;
    for (int s = 0; s < 8; ++s)
      for (const char* n : names[s])
        if (n && e.properties[i].name == n && l.slot[s] < 0) l.slot[s] = int(i);
    if (e.properties[i].name == "texture_s") l.slot[6] = l.slot[6] < 0 ? int(i) : l.slot[6];
    if (e.properties[i].name == "texture_t") l.slot[7] = l.slot[7] < 0 ? int(i) : l.slot[7];
  }
  return l;
}

// Lower bound on one instance's size in the body (for rejecting absurd counts before allocating).
size_t min_instance_size(const Element& e, Format f) {
  size_t n = 0;
  for (const Property& p : e.properties) n += f == Format::ascii ? 2 : scalar_size(p.is_list ? p.count_type : p.type);
  return n;
}

}  // namespace

PlyMesh parse_ply(const std::string& bytes, const std::string& name) {
  const Header h = parse_header(bytes, name);
  BodyReader in(bytes, h.body_offset, h.format, name, h.body_line);
  PlyMesh mesh;
  bool have_vertices = false, have_faces = false;
  std::vector<double> values;
  std::vector<uint32_t> face;
  for (const Element& e : h.elements) {
    const bool is_vertex = e.name == "vertex" && !have_vertices;
    const bool is_face = e.name == "face" && !have_faces;
    // Another element without properties occupies no bytes: nothing to read however large its
    // count (looping over a count of 2^64 empty instances would hang).
    if (e.properties.empty() && !is_vertex && !is_face) continue;
    const size_t min_size = min_instance_size(e, h.format);
    if (min_size > 0 && e.count > in.remaining() / min_size) {
      in.set_context(e.name, 0);
      in.fail("element count " + std::to_string(e.count) + " exceeds the data in the file (truncated?)");
    }
    VertexLayout layout;
    int index_list = -1;
    if (is_vertex) {
      layout = vertex_layout(e);
      if (layout.slot[0] < 0 || layout.slot[1] < 0 || layout.slot[2] < 0)
        throw Error(FileLoc{name}, "element 'vertex' lacks one of the properties x, y, z");
      mesh.positions.reserve(e.count);
      if (layout.slot[3] >= 0 && layout.slot[4] >= 0 && layout.slot[5] >= 0) mesh.normals.reserve(e.count);
      else layout.slot[3] = layout.slot[4] = layout.slot[5] = -1;
      if (layout.slot[6] >= 0 && layout.slot[7] >= 0) mesh.uvs.reserve(e.count);
      else layout.slot[6] = layout.slot[7] = -1;
    }
    if (is_face) {
      for (size_t i = 0; i < e.properties.size(); ++i)
        if (e.properties[i].is_list && (e.properties[i].name == "vertex_indices" || e.properties[i].name == "vertex_index"))
          index_list = int(i);
      if (index_list < 0) throw Error(FileLoc{name}, "element 'face' has no list property vertex_indices");
      if (!is_integer(e.properties[size_t(index_list)].type))
        throw Error(FileLoc{name}, "face vertex indices must have an integer type");
    }
    values.assign(e.properties.size(), 0.0);
    for (uint64_t k = 0; k < e.count; ++k) {
      in.set_context(e.name, k);
      for (size_t pi = 0; pi < e.properties.size(); ++pi) {
        const Property& p = e.properties[pi];
        if (!p.is_list) {
          values[pi] = in.read(p.type);
          continue;
        }
        const double count = in.read(p.count_type);
        if (count < 0 || count > 1e6) in.fail("bad list length " + std::to_string(count));
        const bool keep = int(pi) == index_list;
        if (keep) face.clear();
        for (int i = 0; i < int(count); ++i) {
          const double v = in.read(p.type);
          if (!keep) continue;
          if (v < 0 || v >= double(mesh.positions.size()))
            in.fail("vertex index " + std::to_string(int64_t(v)) + " out of range [0, " + std::to_string(mesh.positions.size()) + ")");
          face.push_back(uint32_t(v));
        }
      }
      if (is_vertex) {
        // "= Vec3(...)": with "Vec3 p(float(values[...]), ...)" clang sees a function declaration.
        const Vec3 p = Vec3(float(values[size_t(layout.slot[0])]), float(values[size_t(layout.slot[1])]), float(values[size_t(layout.slot[2])]));
        if (!all_finite(p)) in.fail("vertex position is NaN or infinite");
        mesh.positions.push_back(p);
        if (layout.slot[3] >= 0) {
          const Vec3 n = Vec3(float(values[size_t(layout.slot[3])]), float(values[size_t(layout.slot[4])]), float(values[size_t(layout.slot[5])]));
          if (!all_finite(n)) in.fail("vertex normal is NaN or infinite");
          mesh.normals.push_back(n);
        }
        if (layout.slot[6] >= 0) {
          const float u = float(values[size_t(layout.slot[6])]), v = float(values[size_t(layout.slot[7])]);
          if (!std::isfinite(u) || !std::isfinite(v)) in.fail("vertex texture coordinate is NaN or infinite");
          mesh.uvs.push_back({u, v});
        }
      } else if (is_face) {
        if (face.size() < 3) in.fail("face with " + std::to_string(face.size()) + " vertices (at least 3 needed)");
        if (face.size() > 3) ++mesh.polygon_faces;
        for (size_t i = 1; i + 1 < face.size(); ++i) mesh.indices.insert(mesh.indices.end(), {face[0], face[i], face[i + 1]});
      }
    }
    have_vertices |= is_vertex;
    have_faces |= is_face;
  }
  if (!have_vertices) throw Error(FileLoc{name}, "no 'vertex' element");
  if (!have_faces) throw Error(FileLoc{name}, "no 'face' element");
  return mesh;
}

PlyMesh read_ply(const std::string& path) { return parse_ply(read_file_bytes(path), path); }

}  // namespace pathspace
