// Mitsuba XML document: parsing, locations, parameters (see mitsuba_xml.h). Parameters follow
// Mitsuba 3: a <default> only applies when no value was given from outside (`render -D NAME=VALUE`),
// and an unknown $name is an error rather than silently left in place.
#include "pathspace/io/mitsuba/mitsuba_xml.h"

#include "pathspace/io/scene_loader.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>

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

Document::Document(const std::string& bytes, std::string name, const std::vector<std::pair<std::string, std::string>>& defines)
    : name_(std::move(name)) {
  for (const auto& [key, value] : defines) {
    if (!is_scene_parameter_name(key)) throw Error("-D " + key + "=...: a parameter name is made of letters, digits and '_'");
    params_[key] = value;  // the last -D of a name wins, as on a command line
  }
  line_starts_.push_back(0);
  for (size_t i = 0; i < bytes.size(); ++i)
    if (bytes[i] == '\n') line_starts_.push_back(i + 1);
  const pugi::xml_parse_result r = doc_.load_buffer(bytes.data(), bytes.size(), pugi::parse_default, pugi::encoding_utf8);
  if (!r) throw Error(loc_at(size_t(std::max<ptrdiff_t>(0, r.offset))), std::string("XML syntax error: ") + r.description());
  scene_ = doc_.child("scene");
  if (!scene_) throw Error(FileLoc{name_}, "no <scene> element at the top level");
  for (const pugi::xml_node& d : scene_.children("default")) {
    const std::string key = d.attribute("name").value();
    if (!is_scene_parameter_name(key)) throw Error(loc(d), "<default> needs a name made of letters, digits and '_'");
    if (!d.attribute("value")) throw Error(loc(d), "<default name=\"" + key + "\"> has no value");
    params_.emplace(key, d.attribute("value").value());  // -D, then the first definition wins
  }
  for (const pugi::xml_node& p : scene_.children("path")) {
    const std::string value = attr(p, "value");
    if (value.empty()) throw Error(loc(p), "<path> needs a value (a folder)");
    search_paths_.push_back(value);
  }
  for (const pugi::xml_node& t : scene_.children("texture")) {
    const std::string id = attr(t, "id");
    if (!id.empty()) textures_.emplace(id, t);
  }
  const std::string version = attr(scene_, "version", "");
  legacy_ = !version.empty() && (version[0] == '0' || version[0] == '1') && version.size() > 1 && version[1] == '.';
}

FileLoc Document::loc_at(size_t offset) const {
  const auto it = std::upper_bound(line_starts_.begin(), line_starts_.end(), offset);
  const size_t line = size_t(it - line_starts_.begin());  // 1-based: the count of line starts <= offset
  return FileLoc{name_, int(line), int(offset - line_starts_[line - 1]) + 1};
}

FileLoc Document::loc(const pugi::xml_node& node) const {
  const ptrdiff_t off = node.offset_debug();
  if (off < 0) return FileLoc{name_};
  // offset_debug points at the element name; report the '<' before it, where editors put the cursor.
  return loc_at(size_t(off > 0 ? off - 1 : 0));
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
