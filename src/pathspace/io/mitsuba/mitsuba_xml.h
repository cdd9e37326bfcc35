// A Mitsuba scene document (pugixml) with what every reader of it needs: file:line locations for
// nodes (pugixml only knows byte offsets), `<default>` parameters and `$name` substitution in
// attribute values, and the version's naming (0.x camelCase property names become Mitsuba 3's
// snake_case, as Mitsuba 3's own upgrade path does), plus the number parsing shared by the readers.
#pragma once

#include <pugixml.hpp>

#include <filesystem>
#include <map>
#include <set>
#include <unordered_map>
#include <string>
#include <utility>
#include <vector>

#include "pathspace/base/error.h"

namespace pathspace::mitsuba {

class Document {
 public:
  // Parses `bytes` (the text of file `name` in `folder`); an XML syntax error is an Error at
  // file:line:column. `defines` are parameters given from outside: they take the place of the
  // file's <default>s, and each must name a <default> or a $name of the file. Top-level
  // <include filename="..."/> elements are replaced by the children of the included file's <scene>
  // (found like any file name, resolve_file), whose nodes keep their own file:line:column.
  Document(const std::string& bytes, std::string name, const std::vector<std::pair<std::string, std::string>>& defines = {},
           std::string folder = ".");
  Document(const Document&) = delete;
  Document& operator=(const Document&) = delete;

  pugi::xml_node scene() const { return scene_; }
  const std::string& name() const { return name_; }
  // Version 0.x (camelCase names: maxDepth, toWorld) rather than 2/3 (max_depth, to_world).
  bool legacy() const { return legacy_; }
  FileLoc loc(const pugi::xml_node& node) const;

  // Attribute value after `$parameter` substitution; `fallback` when the attribute is absent.
  std::string attr(const pugi::xml_node& node, const char* key, const std::string& fallback = "") const;
  bool has_attr(const pugi::xml_node& node, const char* key) const { return bool(node.attribute(key)); }
  // The node's `name` attribute in snake_case.
  std::string prop_name(const pugi::xml_node& node) const;
  // The top-level <texture id="..."> with this id, for <ref name="reflectance" id="..."/>; null if none.
  pugi::xml_node texture(const std::string& id) const;
  // Where a file name of the scene (mesh, texture, environment map) points: as given when absolute;
  // else `folder`/name when that exists, else the first folder of the scene's <path value="..."/>
  // elements (in file order, relative to `folder`) that holds it, else `folder`/name (for the
  // not-found message), as Mitsuba's file resolver does.
  std::filesystem::path resolve_file(const std::string& name, const std::string& folder) const;

 private:
  FileLoc loc_at(size_t offset) const;
  std::string substitute(const std::string& value, const pugi::xml_node& node) const;
  void read_defaults();
  void expand_includes();
  void check_defines_are_parameters(const std::vector<std::pair<std::string, std::string>>& defines) const;

  pugi::xml_document doc_;
  pugi::xml_node scene_;
  std::string name_;
  std::vector<size_t> line_starts_;
  std::map<std::string, std::string> params_;
  std::set<std::string> declared_;  // names of the <default>s
  std::map<std::string, pugi::xml_node> textures_;
  std::vector<std::string> search_paths_;  // <path value="..."/>
  std::string folder_;
  std::unordered_map<const void*, FileLoc> copied_locs_;  // node (internal object) -> where it was written
  bool legacy_ = false;
};

// camelCase -> snake_case at lower-to-upper transitions: "maxDepth" -> "max_depth", "intIOR" -> "int_ior".
std::string snake_case(const std::string& name);
// Numbers separated by whitespace and/or commas ("1, 2 3"); anything else, NaN or inf is an Error at loc.
std::vector<double> parse_numbers(const std::string& text, const FileLoc& loc);
double parse_number(const std::string& text, const FileLoc& loc);

}  // namespace pathspace::mitsuba
