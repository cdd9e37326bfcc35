// OBJ/MTL loading (see obj_loader.h). tinyobjloader parses; this file validates indices, maps the
// materials and reports what it cannot represent. Diffuse and Phong lobes are made two-sided because
// OBJ files rarely orient their faces consistently. map_Kd / map_Ks bind image textures; corners
// with texture coordinates or normals get their own vertices (OBJ indexes v, vt and vn separately).
#include "pathspace/io/obj_loader.h"

#include <tiny_obj_loader.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <limits>
#include <map>
#include <sstream>
#include <tuple>

#include "pathspace/io/file_bytes.h"
#include "pathspace/io/texture_file.h"

namespace pathspace {

namespace {

Rgb rgb(const tinyobj::real_t* v) { return Rgb(float(v[0]), float(v[1]), float(v[2])); }

// tinyobjloader skips statements it does not know without a word, and reports bad face indices
// without a line: list unknown statements with their lines, and fail at the first face that names
// a vertex that does not exist (positive indices count from the file's first vertex, negative ones
// back from the last vertex defined so far, 0 is invalid).
void scan_statements(const std::string& path, const std::string& text, LoadWarnings* w) {
  std::istringstream in(text);
  std::string line;
  int line_no = 0;
  int64_t vertices = 0;
  std::vector<std::pair<int, int64_t>> positive;  // (line, index): checked against the final count
  static const char* const known[] = {"v", "vn", "vt", "f", "o", "g", "s", "usemtl", "mtllib"};
  while (std::getline(in, line)) {
    ++line_no;
    std::istringstream ss(line);
    std::string word;
    if (!(ss >> word) || word[0] == '#') continue;
    // tinyobjloader reads "nan" or "x" as 0, and a missing coordinate as 0, without a word.
    const int needed = word == "v" || word == "vn" ? 3 : word == "vt" ? 1 : 0;
    if (needed > 0) {
      vertices += word == "v";
      const char* what = word == "v" ? "vertex coordinate" : word == "vn" ? "normal coordinate" : "texture coordinate";
      int count = 0;
      for (std::string c; count < 3 && ss >> c; ++count) {
        double x = 0.0;
        const auto r = std::from_chars(c.data() + (c[0] == '+'), c.data() + c.size(), x);
        if (r.ec != std::errc() || r.ptr != c.data() + c.size() || !(std::fabs(x) <= std::numeric_limits<float>::max()))
          throw Error(FileLoc{path, line_no, 1}, std::string(what) + " '" + c + "' is not a finite float");
      }
      if (count < needed)
        throw Error(FileLoc{path, line_no, 1}, "'" + word + "' has " + std::to_string(count) + " coordinate(s); it needs " +
                                                 (needed == 3 ? "3 (x y z)" : "at least 1 (u [v])"));
    }
    if (word == "f")
      for (std::string ref; ss >> ref;) {
        int64_t i = 0;
        const auto r = std::from_chars(ref.data(), ref.data() + ref.size(), i);
        if (r.ec == std::errc::invalid_argument) continue;  // not a number: tinyobjloader's call
        if (r.ec != std::errc() || i == 0 || (i < 0 && -i > vertices))
          throw Error(FileLoc{path, line_no, 1}, "face vertex index " + ref.substr(0, size_t(r.ptr - ref.data())) + " does not name a vertex (" +
                                                   std::to_string(vertices) + " defined so far)");
        if (i > 0) positive.emplace_back(line_no, i);
      }
    if (std::find_if(std::begin(known), std::end(known), [&](const char* k) { return word == k; }) != std::end(known)) continue;
    w->add(FileLoc{path, line_no, 1}, "OBJ statement '" + word + "' is not supported; ignored");
  }
  for (const auto& [at, i] : positive)
    if (i > vertices)
      throw Error(FileLoc{path, at, 1}, "face vertex index " + std::to_string(i) + " out of range (the file has " + std::to_string(vertices) + " vertices)");
}

// tinyobjloader's skin weights ("vw", its own extension) convert a joint id to int without a range
// check, undefined behaviour for 1e10 or inf (fuzz_obj found it, tests/fuzz/corpus/obj). pathspace
// has no skinning, so those statements are commented out, one byte each, before tinyobjloader
// reads the text; scan_statements has already warned that they are ignored. Lines end at '\n' or
// '\r' and a statement starts after spaces and tabs, as tinyobjloader reads them.
void drop_skin_weights(std::string* text) {
  std::string& t = *text;
  for (size_t i = 0; i < t.size();) {
    size_t j = i;
    while (j < t.size() && (t[j] == ' ' || t[j] == '\t')) ++j;
    if (j + 2 < t.size() && t[j] == 'v' && t[j + 1] == 'w' && (t[j + 2] == ' ' || t[j + 2] == '\t')) t[j] = '#';
    while (i < t.size() && t[i] != '\n' && t[i] != '\r') ++i;
    ++i;
  }
}

// map_Kd / map_Ks (multiplied by Kd / Ks as MTL specifies; a black Kd or Ks counts as white, which
// exporters write next to a map), with the -s / -o uv options and "-colorspace linear". A missing
// or unreadable image is a warning and leaves the constant colour.
int32_t obj_texture(const std::string& name, const tinyobj::texture_option_t& opt, const std::string& obj_path,
                    const std::string& mtl_name, Scene* scene, TextureFiles* files, LoadWarnings* w) {
  std::filesystem::path file(name);
  if (file.is_relative()) file = std::filesystem::path(obj_path).parent_path() / file;
  const LdrEncoding ldr = opt.colorspace == "linear" ? LdrEncoding::linear : LdrEncoding::srgb;
  const TextureUvTransform uv{float(opt.scale[0]), float(opt.scale[1]), float(opt.origin_offset[0]), float(opt.origin_offset[1])};
  try {
    return int32_t(files->add(scene, file.string(), ldr, uv));
  } catch (const Error& e) {
    w->add(FileLoc{obj_path}, "material '" + mtl_name + "': texture '" + name + "' not used (" + e.what() + "); constant colour used");
    return -1;
  }
}

Material obj_material(const tinyobj::material_t& mt, const std::string& path, Scene* scene, TextureFiles* files, LoadWarnings* w) {
  Material m;
  m.two_sided = true;
  const FileLoc loc{path};
  const bool glass = mt.illum == 5 || mt.illum == 7 || (mt.ior > 1.f && mt.dissolve < 1.f);
  if (glass) {
    const float ior = mt.ior > 1.f ? float(mt.ior) : 1.5f;
    const Rgb tint = is_black(rgb(mt.transmittance)) ? Rgb(1.f) : rgb(mt.transmittance);
    m = make_glass(ior, tint);
  } else {
    m.diffuse = rgb(mt.diffuse);
    const Rgb ks = rgb(mt.specular);
    if (!is_black(ks) && mt.shininess > 0.f) {
      m.glossy = ks;
      m.exponent = std::max(1.f, float(mt.shininess));
    }
    // Keep the material energy conserving: Kd + Ks <= 1 per channel.
    const float total = max_component(m.diffuse + m.glossy);
    if (total > 1.f) {
      m.diffuse = m.diffuse / total;
      m.glossy = m.glossy / total;
      w->add(loc, "material '" + mt.name + "': Kd + Ks > 1, scaled down by " + std::to_string(total));
    }
    if (mt.dissolve < 1.f) w->add(loc, "material '" + mt.name + "': transparency d < 1 without Ni > 1 is not supported; opaque");
  }
  if (!glass && !mt.diffuse_texname.empty()) {
    m.diffuse_texture = obj_texture(mt.diffuse_texname, mt.diffuse_texopt, path, mt.name, scene, files, w);
    if (m.diffuse_texture >= 0 && is_black(m.diffuse)) m.diffuse = Rgb(1.f);
  }
  if (!glass && !mt.specular_texname.empty() && !is_black(m.glossy))
    m.glossy_texture = obj_texture(mt.specular_texname, mt.specular_texopt, path, mt.name, scene, files, w);
  if (!mt.bump_texname.empty() || !mt.alpha_texname.empty() || !mt.normal_texname.empty() || !mt.emissive_texname.empty() ||
      (glass && !mt.diffuse_texname.empty()))
    w->add(loc, "material '" + mt.name + "': only map_Kd and map_Ks are supported; other maps ignored");
  return m;
}

// tinyobjloader reads a number it cannot parse ("nan", "1,5") in a material statement as 0 and a
// missing one as its default, without a word: check the numeric statements pathspace uses first.
void scan_material_numbers(const std::string& path, const std::string& text) {
  static const std::map<std::string, int> kCounts = {{"Ka", 3}, {"Kd", 3}, {"Ks", 3}, {"Ke", 3}, {"Tf", 3},
                                                     {"Ni", 1}, {"Ns", 1}, {"d", 1},  {"Tr", 1}, {"illum", 1}};
  std::istringstream in(text);
  int line_no = 0;
  for (std::string line; std::getline(in, line);) {
    ++line_no;
    std::istringstream ss(line);
    std::string word;
    if (!(ss >> word)) continue;
    const auto it = kCounts.find(word);
    if (it == kCounts.end()) continue;
    std::vector<std::string> values;
    for (std::string v; ss >> v;) values.push_back(v);
    if (values.size() == 2 && values[0] == "spectral") continue;  // Tf spectral file: not read
    if (!values.empty() && (values[0] == "xyz" || values[0] == "-halo")) values.erase(values.begin());
    // One value stands for all three channels (Kd 0.5), as tinyobjloader reads it.
    if (values.empty() || (values.size() != 1 && int(values.size()) < it->second))
      throw Error(FileLoc{path, line_no, 1}, "'" + word + "' needs " + std::to_string(it->second) + " number(s)");
    for (const std::string& v : values) {
      double x = 0.0;
      const auto r = std::from_chars(v.data() + (v[0] == '+'), v.data() + v.size(), x);
      if (r.ec != std::errc() || r.ptr != v.data() + v.size() || !std::isfinite(x))
        throw Error(FileLoc{path, line_no, 1}, "'" + word + "' value '" + v + "' is not a finite number");
    }
  }
}

// Material files next to the OBJ, as tinyobjloader's MaterialFileReader finds them, but read through
// read_file_bytes: its checks (no FIFO, no device) and gzip, with errors that name the file.
class MtlReader final : public tinyobj::MaterialReader {
 public:
  explicit MtlReader(std::string folder) : folder_(std::move(folder)) {}
  bool operator()(const std::string& name, std::vector<tinyobj::material_t>* materials, std::map<std::string, int>* by_name,
                  std::string* warning, std::string* error) override {
    const std::string path = folder_ + name;
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) {  // as tinyobjloader: a missing library is a warning
      *warning += "Material file [ " + name + " ] not found in a path : " + folder_ + "\n";
      return false;
    }
    const std::string text = read_file_bytes(path);
    scan_material_numbers(path, text);
    std::istringstream in(text);
    tinyobj::LoadMtl(by_name, materials, &in, warning, error);
    return true;
  }

 private:
  std::string folder_;
};

}  // namespace

void load_obj_into(const std::string& path, LoadWarnings* warnings, Scene* scene) {
  std::string text = read_file_bytes(path);
  scan_statements(path, text, warnings);
  drop_skin_weights(&text);
  std::istringstream in(text);
  // Material files next to the OBJ, as tinyobjloader's ObjReader::ParseFromFile finds them.
  const std::string folder = std::filesystem::path(path).parent_path().string();
  MtlReader mtl_reader(folder.empty() ? std::string() : folder + "/");
  tinyobj::attrib_t attrib;
  std::vector<tinyobj::shape_t> shapes;
  std::vector<tinyobj::material_t> materials;
  std::string warning, error;
  if (!tinyobj::LoadObj(&attrib, &shapes, &materials, &warning, &error, &in, &mtl_reader, /*triangulate=*/true,
                        /*default_vcols_fallback=*/false) ||
      !error.empty())
    throw Error(FileLoc{path}, "cannot read OBJ: " + (error.empty() ? std::string("parse failed") : error));
  std::istringstream tw(warning);
  for (std::string line; std::getline(tw, line);)
    if (!line.empty()) warnings->add(FileLoc{path}, line);

  std::vector<uint32_t> material_index;
  std::vector<Rgb> material_emission;
  TextureFiles texture_files;
  for (const tinyobj::material_t& mt : materials) {
    material_index.push_back(scene->add_material(obj_material(mt, path, scene, &texture_files, warnings)));
    material_emission.push_back(rgb(mt.emission));
  }
  int default_material = -1;
  const size_t num_vertices = attrib.vertices.size() / 3;
  const uint32_t base = uint32_t(scene->positions.size());
  for (size_t i = 0; i < num_vertices; ++i) {
    const Vec3 p(attrib.vertices[3 * i], attrib.vertices[3 * i + 1], attrib.vertices[3 * i + 2]);
    if (!all_finite(p)) throw Error(FileLoc{path}, "vertex " + std::to_string(i + 1) + " is NaN or infinite");
    scene->positions.push_back(p);
  }
  // A corner with a texture coordinate or a normal becomes its own vertex, shared by equal corners.
  std::map<std::tuple<int, int, int>, uint32_t> corner_vertices;
  const size_t num_uvs = attrib.texcoords.size() / 2, num_normals = attrib.normals.size() / 3;
  auto corner_vertex = [&](const tinyobj::index_t& idx) -> uint32_t {
    const bool has_uv = idx.texcoord_index >= 0 && size_t(idx.texcoord_index) < num_uvs;
    const bool has_n = idx.normal_index >= 0 && size_t(idx.normal_index) < num_normals;
    if (!has_uv && !has_n) return base + uint32_t(idx.vertex_index);
    const auto key = std::make_tuple(idx.vertex_index, has_uv ? idx.texcoord_index : -1, has_n ? idx.normal_index : -1);
    const auto it = corner_vertices.find(key);
    if (it != corner_vertices.end()) return it->second;
    const uint32_t v = uint32_t(scene->positions.size());
    const Vec3 p = scene->positions[base + uint32_t(idx.vertex_index)];
    scene->positions.push_back(p);
    if (has_uv) {
      scene->uvs.resize(v);
      const size_t t = size_t(idx.texcoord_index);
      scene->uvs.push_back(Point2{float(attrib.texcoords[2 * t]), float(attrib.texcoords[2 * t + 1])});
    }
    if (has_n) {
      scene->normals.resize(v);
      const size_t n = size_t(idx.normal_index);
      const Vec3 nv(attrib.normals[3 * n], attrib.normals[3 * n + 1], attrib.normals[3 * n + 2]);
      scene->normals.push_back(all_finite(nv) ? nv : Vec3());
    }
    corner_vertices.emplace(key, v);
    return v;
  };
  for (const tinyobj::shape_t& shape : shapes) {
    if (!shape.lines.indices.empty() || !shape.points.indices.empty())
      warnings->add(FileLoc{path}, "shape '" + shape.name + "': lines and points are not rendered");
    const tinyobj::mesh_t& mesh = shape.mesh;
    size_t offset = 0;
    for (size_t f = 0; f < mesh.num_face_vertices.size(); ++f) {
      const size_t nv = mesh.num_face_vertices[f];
      if (nv != 3) throw Error(FileLoc{path}, "shape '" + shape.name + "': face " + std::to_string(f) + " was not triangulated");
      uint32_t v[3];
      for (size_t k = 0; k < 3; ++k) {
        const tinyobj::index_t idx = mesh.indices[offset + k];
        if (idx.vertex_index < 0 || size_t(idx.vertex_index) >= num_vertices)
          throw Error(FileLoc{path}, "shape '" + shape.name + "': face " + std::to_string(f) + " references a missing vertex");
        v[k] = corner_vertex(idx);
      }
      offset += nv;
      const int mid = f < mesh.material_ids.size() ? mesh.material_ids[f] : -1;
      uint32_t material;
      Rgb le;
      if (mid >= 0 && size_t(mid) < material_index.size()) {
        material = material_index[size_t(mid)];
        le = material_emission[size_t(mid)];
      } else {
        if (default_material < 0) {
          Material m = make_diffuse(Rgb(0.5f));
          m.two_sided = true;
          default_material = int(scene->add_material(m));
        }
        material = uint32_t(default_material);
      }
      const Vec3 ng = cross(scene->positions[v[1]] - scene->positions[v[0]], scene->positions[v[2]] - scene->positions[v[0]]);
      if (!is_black(le) && !(length(ng) > 0.f)) continue;  // a zero-area emitter cannot be sampled
      Triangle tri{{v[0], v[1], v[2]}, material, kNoLight};
      if (!is_black(le)) {
        Light l;
        l.type = LightType::area_triangle;
        l.shape = uint32_t(scene->triangles.size());
        l.value = le;
        tri.light = int32_t(scene->lights.size());
        scene->lights.push_back(l);
      }
      scene->triangles.push_back(tri);
    }
  }
}

}  // namespace pathspace
