// pbrt-v4 statement grammar (see pbrt_parser.h). Each directive has a fixed shape: some leading
// string arguments, some numbers, and for most a parameter list of "type name" value pairs. A table
// gives the shape, so the grammar is data rather than one function per directive.
#include "pathspace/io/pbrt/pbrt_parser.h"

#include <charconv>
#include <cmath>
#include <filesystem>
#include <limits>

#include "pathspace/io/file_bytes.h"
#include "pathspace/io/pbrt/pbrt_paths.h"
#include "pathspace/io/pbrt/pbrt_tokenizer.h"

namespace pathspace::pbrt {

namespace {

constexpr int kMaxIncludeDepth = 32;

struct Shape {
  const char* directive;
  int strings;    // leading quoted strings (-1: one or two, MediumInterface)
  int numbers;    // leading numbers (16 for matrices: brackets optional)
  bool params;    // followed by a parameter list
};

const Shape kShapes[] = {
    {"WorldBegin", 0, 0, false},     {"WorldEnd", 0, 0, false},        {"AttributeBegin", 0, 0, false},
    {"AttributeEnd", 0, 0, false},   {"TransformBegin", 0, 0, false},  {"TransformEnd", 0, 0, false},
    {"ObjectEnd", 0, 0, false},      {"ReverseOrientation", 0, 0, false}, {"Identity", 0, 0, false},
    {"Translate", 0, 3, false},      {"Scale", 0, 3, false},           {"Rotate", 0, 4, false},
    {"LookAt", 0, 9, false},         {"Transform", 0, 16, false},      {"ConcatTransform", 0, 16, false},
    {"TransformTimes", 0, 2, false}, {"ActiveTransform", 0, 0, false}, {"CoordinateSystem", 1, 0, false},
    {"CoordSysTransform", 1, 0, false}, {"ColorSpace", 1, 0, false},   {"NamedMaterial", 1, 0, false},
    {"ObjectBegin", 1, 0, false},    {"ObjectInstance", 1, 0, false},  {"Include", 1, 0, false},
    {"Import", 1, 0, false},         {"MediumInterface", -1, 0, false}, {"Option", 0, 0, true},
    {"Camera", 1, 0, true},          {"Film", 1, 0, true},             {"Sampler", 1, 0, true},
    {"Integrator", 1, 0, true},      {"PixelFilter", 1, 0, true},      {"Accelerator", 1, 0, true},
    {"Shape", 1, 0, true},           {"Material", 1, 0, true},         {"MakeNamedMaterial", 1, 0, true},
    {"LightSource", 1, 0, true},     {"AreaLightSource", 1, 0, true},  {"Texture", 3, 0, true},
    {"MakeNamedMedium", 1, 0, true}, {"Attribute", 1, 0, true},
};

double parse_number(const Token& t) {
  double v = 0.0;
  const char* b = t.text.data();
  const char* e = b + t.text.size();
  if (b < e && *b == '+') ++b;
  const auto r = std::from_chars(b, e, v);
  if (r.ec != std::errc() || r.ptr != e) throw Error(t.loc, "expected a number, got '" + std::string(t.text) + "'");
  // from_chars accepts "nan" and "inf"; pbrt's Float is a float, so larger values cannot be meant either.
  if (!(std::fabs(v) <= double(std::numeric_limits<float>::max())))
    throw Error(t.loc, "number '" + std::string(t.text) + "' is not finite or out of the float range");
  return v;
}

class Parser {
 public:
  Parser(const StatementHandler& handler, std::string main_folder) : handler_(handler), main_folder_(std::move(main_folder)) {}

  void parse(const std::string& text, const std::string& name, const std::string& folder, int depth) {
    Tokenizer tok(text, name);
    for (;;) {
      const Token t = tok.next();
      if (t.at_end()) return;
      if (t.is_string() || t.is_open() || t.is_close()) throw Error(t.loc, "expected a directive, got '" + std::string(t.text) + "'");
      const Shape* shape = nullptr;
      for (const Shape& s : kShapes)
        if (t.text == s.directive) shape = &s;
      if (!shape) throw Error(t.loc, "unknown directive '" + std::string(t.text) + "'");
      Statement st;
      st.directive = std::string(t.text);
      st.loc = t.loc;
      read_arguments(tok, *shape, &st);
      if (st.directive == "Include" || st.directive == "Import") {
        include(st, folder, depth);
        continue;
      }
      handler_(st);
    }
  }

 private:
  void read_arguments(Tokenizer& tok, const Shape& shape, Statement* st) {
    const int strings = shape.strings < 0 ? 1 : shape.strings;
    for (int i = 0; i < strings; ++i) st->strings.push_back(expect_string(tok, st->directive));
    if (shape.strings < 0 && tok.peek().is_string()) st->strings.push_back(tok.next().unquoted());
    if (st->directive == "ActiveTransform") {
      const Token w = tok.next();
      if (w.text != "All" && w.text != "StartTime" && w.text != "EndTime") throw Error(w.loc, "ActiveTransform expects All, StartTime or EndTime");
      st->strings.push_back(std::string(w.text));
    }
    if (shape.numbers > 0) {
      const bool bracket = tok.peek().is_open();
      if (bracket) tok.next();
      for (int i = 0; i < shape.numbers; ++i) {
        const Token n = tok.next();
        if (n.at_end() || n.is_string() || n.is_open() || n.is_close())
          throw Error(n.loc, st->directive + " expects " + std::to_string(shape.numbers) + " numbers");
        st->numbers.push_back(parse_number(n));
      }
      if (bracket && !tok.next().is_close()) throw Error(st->loc, st->directive + ": expected ']' after " + std::to_string(shape.numbers) + " numbers");
    }
    if (shape.params)
      while (tok.peek().is_string()) st->params.push_back(read_param(tok));
  }

  static std::string expect_string(Tokenizer& tok, const std::string& directive) {
    const Token t = tok.next();
    if (!t.is_string()) throw Error(t.loc, directive + " expects a quoted string, got '" + std::string(t.text) + "'");
    return t.unquoted();
  }

  static Param read_param(Tokenizer& tok) {
    const Token decl = tok.next();
    Param p;
    p.loc = decl.loc;
    const std::string d = decl.unquoted();
    const size_t a = d.find_first_not_of(" \t"), sp = d.find_first_of(" \t", a);
    const size_t b = sp == std::string::npos ? sp : d.find_first_not_of(" \t", sp);
    if (a == std::string::npos || b == std::string::npos || d.find_first_of(" \t", b) != std::string::npos)
      throw Error(decl.loc, "bad parameter declaration '" + d + "' (expected \"type name\")");
    p.type = d.substr(a, sp - a);
    p.name = d.substr(b);
    static const char* const types[] = {"integer", "float", "point2", "vector2", "point3", "vector3", "normal",
                                        "normal3", "point", "vector", "rgb", "color", "spectrum", "blackbody",
                                        "string", "texture", "bool"};
    bool known = false;
    for (const char* t : types) known |= p.type == t;
    if (!known) throw Error(decl.loc, "unknown parameter type '" + p.type + "'");
    const bool bracket = tok.peek().is_open();
    if (bracket) tok.next();
    for (;;) {
      const Token v = tok.peek();
      if (bracket && v.is_close()) {
        tok.next();
        break;
      }
      if (v.at_end()) throw Error(bracket ? v.loc : decl.loc, bracket ? "missing ']'" : "parameter '" + d + "' has no value");
      if (v.is_open()) throw Error(v.loc, "unexpected '['");
      tok.next();
      if (p.type == "bool") {
        const std::string s = v.is_string() ? v.unquoted() : std::string(v.text);
        if (s != "true" && s != "false") throw Error(v.loc, "bool parameter expects true or false, got '" + s + "'");
        p.bools.push_back(s == "true");
      } else if (v.is_string()) {
        if (p.type != "string" && p.type != "texture" && p.type != "spectrum")
          throw Error(v.loc, "parameter '" + d + "' expects numbers, got a string");
        p.strings.push_back(v.unquoted());
      } else {
        if (p.type == "string" || p.type == "texture") throw Error(v.loc, "parameter '" + d + "' expects a quoted string");
        p.numbers.push_back(parse_number(v));
      }
      if (!bracket) break;
    }
    if (p.numbers.empty() && p.strings.empty() && p.bools.empty()) throw Error(decl.loc, "parameter '" + d + "' has no values");
    if (p.type == "integer")
      for (double x : p.numbers)
        // Range first: converting an out-of-range double to an integer is undefined behaviour.
        if (!(std::fabs(x) <= 2147483647.0) || x != std::floor(x))
          throw Error(decl.loc, "integer parameter '" + p.name + "' needs whole numbers within the 32-bit range");
    return p;
  }

  void include(const Statement& st, const std::string& folder, int depth) {
    if (depth >= kMaxIncludeDepth) throw Error(st.loc, "Include nested too deeply (a cycle?)");
    namespace fs = std::filesystem;
    const fs::path path = resolve_scene_file(st.strings[0], folder, main_folder_);
    std::string text;
    try {
      text = read_file_bytes(path.string());
    } catch (const Error& e) {
      throw Error(st.loc, st.directive + " \"" + st.strings[0] + "\": " + e.what());
    }
    parse(text, path.string(), path.parent_path().string(), depth + 1);
  }

  const StatementHandler& handler_;
  std::string main_folder_;
};

}  // namespace

void parse_file(const std::string& path, const StatementHandler& handler) {
  const std::string text = read_file_bytes(path);
  const std::string folder = std::filesystem::path(path).parent_path().string();
  Parser(handler, folder).parse(text, path, folder, 0);
}

void parse_string(const std::string& text, const std::string& name, const std::string& folder, const StatementHandler& handler) {
  Parser(handler, folder).parse(text, name, folder, 0);
}

}  // namespace pathspace::pbrt
