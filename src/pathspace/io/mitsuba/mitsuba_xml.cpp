// Mitsuba XML document: parsing, locations, parameters (see mitsuba_xml.h). Parameters follow
// Mitsuba 3: a <default> only applies when no value was given from outside (`render -D NAME=VALUE`),
// and an unknown $name is an error rather than silently left in place.
#include "pathspace/io/mitsuba/mitsuba_xml.h"

#include "pathspace/io/file_bytes.h"
#include "pathspace/io/scene_loader.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstring>
#include <set>

namespace pathspace::mitsuba {

namespace {

bool is_ident(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

}  // namespace

std::string snake_case(const std::string& name) {
  std::string out;
  for (size_t i = 0; i < name.size(); ++i) {
    const unsigned char c = static_cast<unsigned char>(name[i]);
    if (std::isupper(c) && i > 0 && (std::islower(static_cast<unsigned char>(name[i - 1])) || std::isdigit(static_cast<unsigned char>(name[i - 1]))))
      out.push_back('_');
    out.push_back(char(std::tolower(c)));
  }
  return out;
}

double parse_number(const std::string& text, const FileLoc& loc) {
  const std::vector<double> v = parse_numbers(text, loc);
  if (v.size() != 1) throw Error(loc, "expected one number, got '" + text + "'");
  return v[0];
}

std::vector<double> parse_numbers(const std::string& text, const FileLoc& loc) {
  std::vector<double> out;
  const char* p = text.data();
  const char* end = p + text.size();
  while (p < end) {
    if (std::isspace(static_cast<unsigned char>(*p)) || *p == ',') {
      ++p;
      continue;
    }
    if (*p == '+') ++p;  // from_chars rejects a leading '+'
    double v = 0.0;
    const auto r = std::from_chars(p, end, v);
    if (r.ec != std::errc() || !std::isfinite(v)) throw Error(loc, "invalid number in '" + text.substr(0, 80) + "'");
    out.push_back(v);
    p = r.ptr;
  }
  return out;
}

namespace {

std::vector<size_t> line_starts_of(const std::string& bytes) {
  std::vector<size_t> starts = {0};
  for (size_t i = 0; i < bytes.size(); ++i)
    if (bytes[i] == '\n') starts.push_back(i + 1);
  return starts;
}

FileLoc loc_in(const std::string& name, const std::vector<size_t>& line_starts, size_t offset) {
  const auto it = std::upper_bound(line_starts.begin(), line_starts.end(), offset);
  const size_t line = size_t(it - line_starts.begin());  // 1-based: the count of line starts <= offset
  return FileLoc{name, int(line), int(offset - line_starts[line - 1]) + 1};
}

// Where pugixml parsed `node` in its own document: offset_debug points at the element name; the
// '<' before it is where editors put the cursor.
FileLoc node_loc(const std::string& name, const std::vector<size_t>& line_starts, const pugi::xml_node& node) {
  const ptrdiff_t off = node.offset_debug();
  if (off < 0) return FileLoc{name};
  return loc_in(name, line_starts, size_t(off > 0 ? off - 1 : 0));
}

constexpr int kMaxIncludes = 256;  // in all, nested ones included: a cycle ends here with an error

}  // namespace

Document::Document(const std::string& bytes, std::string name, const std::vector<std::pair<std::string, std::string>>& defines,
                   std::string folder)
    : name_(std::move(name)), folder_(std::move(folder)) {
  for (const auto& [key, value] : defines) {
    if (!is_scene_parameter_name(key)) throw Error("-D " + key + "=...: a parameter name is made of letters, digits and '_'");
    params_[key] = value;  // the last -D of a name wins, as on a command line
  }
  line_starts_ = line_starts_of(bytes);
  const pugi::xml_parse_result r = doc_.load_buffer(bytes.data(), bytes.size(), pugi::parse_default, pugi::encoding_utf8);
  if (!r) throw Error(loc_at(size_t(std::max<ptrdiff_t>(0, r.offset))), std::string("XML syntax error: ") + r.description());
  scene_ = doc_.child("scene");
  if (!scene_) throw Error(FileLoc{name_}, "no <scene> element at the top level");
  read_defaults();
  for (const pugi::xml_node& p : scene_.children("path")) {
    const std::string value = attr(p, "value");
    if (value.empty()) throw Error(loc(p), "<path> needs a value (a folder)");
    search_paths_.push_back(value);
  }
  expand_includes();
  read_defaults();  // the included files' own, after the including file's
  for (const pugi::xml_node& t : scene_.children("texture")) {
    const std::string id = attr(t, "id");
    if (!id.empty()) textures_.emplace(id, t);
  }
  check_defines_are_parameters(defines);
  const std::string version = attr(scene_, "version", "");
  legacy_ = !version.empty() && (version[0] == '0' || version[0] == '1') && version.size() > 1 && version[1] == '.';
}

void Document::read_defaults() {
  for (const pugi::xml_node& d : scene_.children("default")) {
    const std::string key = d.attribute("name").value();
    if (!is_scene_parameter_name(key)) throw Error(loc(d), "<default> needs a name made of letters, digits and '_'");
    declared_.insert(key);
    if (!d.attribute("value")) throw Error(loc(d), "<default name=\"" + key + "\"> has no value");
    params_.emplace(key, d.attribute("value").value());  // -D, then the first definition wins
  }
}

// A -D that no <default> declares and no $name uses would change nothing: a misspelt name, or a
// parameter of another scene. Mitsuba 3 refuses it too.
void Document::check_defines_are_parameters(const std::vector<std::pair<std::string, std::string>>& defines) const {
  std::set<std::string> known = declared_;
  std::vector<pugi::xml_node> stack = {scene_};
  while (!stack.empty()) {
    const pugi::xml_node n = stack.back();
    stack.pop_back();
    for (const pugi::xml_attribute& a : n.attributes())
      for (const char* p = std::strchr(a.value(), '$'); p; p = std::strchr(p + 1, '$')) {
        const char* e = p + 1;
        while (is_ident(*e)) ++e;
        known.emplace(p + 1, e);
      }
    for (const pugi::xml_node& c : n.children())
      if (c.type() == pugi::node_element) stack.push_back(c);
  }
  for (const auto& [key, value] : defines) {
    if (known.count(key)) continue;
    std::string names;
    for (const std::string& k : known)
      if (!k.empty()) names += (names.empty() ? "" : ", ") + k;
    throw Error(FileLoc{name_}, "-D " + key + "=" + value + ": the scene has no parameter '" + key + "' (its parameters: " +
                                    (names.empty() ? "none" : names) + ")");
  }
}

void Document::expand_includes() {
  int count = 0;
  for (pugi::xml_node n = scene_.first_child(); n;) {
    if (n.type() != pugi::node_element || std::string(n.name()) != "include") {
      n = n.next_sibling();
      continue;
    }
    const FileLoc at = loc(n);
    if (++count > kMaxIncludes) throw Error(at, "more than " + std::to_string(kMaxIncludes) + " <include>s (does a file include itself?)");
    const std::string file = attr(n, "filename");
    if (file.empty()) throw Error(at, "<include> needs a filename");
    const std::filesystem::path path = resolve_file(file, folder_);
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec))
      throw Error(at, "included file '" + file + "' not found (looked for " + path.string() + ")");
    // Parsed on its own; its nodes' locations are taken while they are copied, so it is not kept.
    const std::string name = path.string(), bytes = read_file_bytes(name);
    const std::vector<size_t> line_starts = line_starts_of(bytes);
    pugi::xml_document included;
    const pugi::xml_parse_result r = included.load_buffer(bytes.data(), bytes.size(), pugi::parse_default, pugi::encoding_utf8);
    if (!r) throw Error(loc_in(name, line_starts, size_t(std::max<ptrdiff_t>(0, r.offset))), std::string("XML syntax error: ") + r.description());
    const pugi::xml_node inc_scene = included.child("scene");
    if (!inc_scene) throw Error(FileLoc{name}, "no <scene> element at the top level (included at " + at.to_string() + ")");
    // Its elements take the place of the <include>, each copied node mapped to where it was written.
    for (const pugi::xml_node& child : inc_scene.children()) {
      if (child.type() != pugi::node_element) continue;
      const pugi::xml_node copy = scene_.insert_copy_before(child, n);
      std::vector<std::pair<pugi::xml_node, pugi::xml_node>> stack = {{child, copy}};
      while (!stack.empty()) {
        const auto [from, to] = stack.back();
        stack.pop_back();
        copied_locs_[to.internal_object()] = node_loc(name, line_starts, from);
        for (pugi::xml_node a = from.first_child(), b = to.first_child(); a && b; a = a.next_sibling(), b = b.next_sibling())
          stack.emplace_back(a, b);
      }
    }
    scene_.remove_child(n);
    // Scan again from the start, so that the included file's own includes are expanded too (top-level
    // children only: cheap).
    n = scene_.first_child();
  }
}

FileLoc Document::loc_at(size_t offset) const { return loc_in(name_, line_starts_, offset); }

FileLoc Document::loc(const pugi::xml_node& node) const {
  const auto copied = copied_locs_.find(node.internal_object());
  if (copied != copied_locs_.end()) return copied->second;
  return node_loc(name_, line_starts_, node);
}

std::string Document::substitute(const std::string& value, const pugi::xml_node& node) const {
  if (value.find('$') == std::string::npos) return value;
  std::string out;
  for (size_t i = 0; i < value.size();) {
    if (value[i] != '$') {
      out.push_back(value[i++]);
      continue;
    }
    size_t j = i + 1;
    while (j < value.size() && is_ident(value[j])) ++j;
    const std::string key = value.substr(i + 1, j - i - 1);
    const auto it = params_.find(key);
    if (it == params_.end())
      throw Error(loc(node), "undefined parameter '$" + key + "' (no <default name=\"" + key + "\" .../> and no -D " + key + "=VALUE)");
    out += it->second;
    i = j;
  }
  return out;
}

std::string Document::attr(const pugi::xml_node& node, const char* key, const std::string& fallback) const {
  const pugi::xml_attribute a = node.attribute(key);
  return a ? substitute(a.value(), node) : fallback;
}

std::filesystem::path Document::resolve_file(const std::string& name, const std::string& folder) const {
  namespace fs = std::filesystem;
  const fs::path p(name);
  if (p.is_absolute()) return p;
  const fs::path here = fs::path(folder) / p;
  std::error_code ec;
  if (fs::exists(here, ec)) return here;
  for (const std::string& dir : search_paths_) {
    fs::path candidate = fs::path(dir).is_absolute() ? fs::path(dir) / p : fs::path(folder) / dir / p;
    if (fs::exists(candidate, ec)) return candidate;
  }
  return here;
}

pugi::xml_node Document::texture(const std::string& id) const {
  const auto it = textures_.find(id);
  return it == textures_.end() ? pugi::xml_node() : it->second;
}

std::string Document::prop_name(const pugi::xml_node& node) const {
  const std::string n = attr(node, "name");
  return legacy_ ? snake_case(n) : n;
}

}  // namespace pathspace::mitsuba
