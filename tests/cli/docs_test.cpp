// The documentation names only things that exist. Reads README.md and every docs/**/*.md (the
// output folders docs/figures and docs/study-pclt hold no Markdown except the hand-written
// docs/study-pclt/README.md) and checks, line by line:
//  * repository paths: in prose, any token starting with a top-level folder (src/, tests/, apps/,
//    bench/, docs/, scripts/, scenes/, cmake/, tools/, python/, examples/, .ci/); in code spans, fenced blocks and
//    links also short forms whose first folder is one of src/pathspace/, tests/, bench/ or apps/
//    (integrators/pt/pt_kernel.h = src/pathspace/integrators/pt/pt_kernel.h, unit/x_test.cpp =
//    tests/unit/x_test.cpp), bare *.md names, and link targets. `*` is a wildcard, a <placeholder>
//    ends the check at its folder;
//  * command-line options (--name): each must appear in a help text of the pathspace binary
//    (kHelpCommands) unless it belongs to another tool (kOtherToolsOptions);
//  * integrators given to -i / --integrator (NAME or a|b|c): each must be listed by
//    `pathspace info --integrators --json`;
//  * denials: no line may say that a registered integrator, filter or device does not exist, is not
//    implemented or not built, or that there is no such thing ("there is no CUDA backend"), while
//    `pathspace info --json` lists it. A registered thing is named by its name in a code span, its
//    option (`-i pt`, `--filter hashed`, `--device cuda`), its name and kind ("hashed filter", "cuda
//    backend") or what the pages call it (kDenialAliases: "path tracer", "GPU path tracer"). A clause
//    that is conditional or says where something runs ("without nvcc ...", "... on the GPU") is not
//    a denial. Lines are checked one by one, code blocks not at all.
// And the other way round, the sections the code cites: a comment that points at
// docs/<page>.md, "<title>" (or docs/<page>.md "<title>") names a page that exists and a heading or a
// bullet of it that begins with the title.
// Lines between <!-- docs-test: off --> and <!-- docs-test: on --> (a worked example of code that
// does not exist) are not checked.
// A failure names the document, the line and the missing thing. The checkers themselves are tested
// on made-up documents (DocsCheck.FindsMissingThings, DocsCheck.FindsDenialsOfRegisteredThings), so
// they cannot pass by finding nothing.
#include <fnmatch.h>
#include <sys/wait.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "cli_process.h"
#include <nlohmann/json.hpp>

namespace {

namespace fs = std::filesystem;
using pathspace::testing::read_all;
using pathspace::testing::run_pathspace;
using pathspace::testing::Run;

const fs::path kRoot = PATHSPACE_SOURCE_DIR;

// Help texts whose --options the documentation may name.
const char* const kHelpCommands[] = {"--help", "render --help", "view --help", "info --help", "compare --help", "study --help",
                                     "study pclt --help", "study psf --help"};

// Options of other tools that the documentation shows in commands. Exact names, or prefixes
// ending in '_' for tools whose flags share one.
const std::set<std::string> kOtherToolsOptions = {
    "--preset",                  // cmake --preset, ctest --preset
    "--build",                   // cmake --build
    "--target",                  // cmake --build ... --target
    "--test-dir",                // ctest --test-dir
    "--output-on-failure",       // ctest
    "--version",                 // gcc/cmake/nvcc --version
    "--no-install-recommends",   // apt-get install
    "--fuzz",                    // scripts/install-deps --fuzz (a script, not the pathspace binary)
    "--render",                  // scripts/build --render, scripts/install-deps --render
    "--expt-relaxed-constexpr",  // nvcc
    "--fmad",                    // nvcc
    "--runs",                    // bench/cuda/cuda_filter_bench, bench/ray_replay_bench, bench/smallvcm/side_by_side.py
    "--size",                    // bench/ray_replay_bench
    "--smallvcm",                // bench/smallvcm/side_by_side.py
    "--bundle",                  // scripts/gpu-check
    "--scenes",                  // scripts/gpu-check, bench/gpu_render_bench
    "--frames",                  // (also pathspace render) bench/gpu_render_bench
    "--no-sanitizer",            // scripts/gpu-check
    "--vertices",                // scripts/gpu-check
    "--benchmark_",              // Google Benchmark: --benchmark_filter, --benchmark_out, ...
    "--gtest_",                  // GoogleTest: --gtest_filter, ...
    "--allow-run-as-root",       // mpirun (docs/distributed.md)
    "--oversubscribe",           // mpirun
    "--hostfile",                // mpirun
    "--map-by",                  // mpirun
    "--ntasks-per-node",         // srun
    "--cpus-per-task",           // srun
    "--nodes",                   // srun
    "--system-site-packages",    // python3 -m venv (docs/python.md)
    "--no-build-isolation",      // pip install (docs/python.md)
    "--interactive",             // pbrt-v4 (docs/viewer.md: the viewer's key conventions)
    "--keep",                    // tests/browser/*.py
    "--pathspace",               // tests/browser/*.py, bench/viewer_rate.py
};

// Folders at the repository root: a token starting with one of them is a repository path
// wherever it appears.
const char* const kTopFolders[] = {"src", "tests", "apps", "bench", "docs", "scripts", "scenes", "cmake", "tools", "python", "examples", ".ci"};
// Folders whose sub-folders the documentation names without the prefix (in code and links only).
const char* const kShortBases[] = {"src/pathspace", "tests", "bench", "apps", "src"};

struct Finding {
  std::string where;  // "docs/cli.md:12"
  std::string what;
};

struct DocLine {
  std::string file;  // relative to the repository root
  int number = 0;
  std::string text;
  bool fenced = false;  // inside a ``` block
};

std::vector<DocLine> split_lines(const std::string& file, const std::string& content) {
  std::vector<DocLine> lines;
  std::istringstream in(content);
  std::string text;
  bool fenced = false;
  int number = 0;
  bool off = false;
  while (std::getline(in, text)) {
    ++number;
    // A worked example of code that does not exist (a hypothetical integrator) is fenced off with
    // <!-- docs-test: off --> ... <!-- docs-test: on -->.
    if (text.find("<!-- docs-test: off") != std::string::npos) off = true;
    if (text.find("<!-- docs-test: on") != std::string::npos) off = false;
    if (off) continue;
    const bool fence = text.find_first_not_of(' ') != std::string::npos &&
                       text.compare(text.find_first_not_of(' '), 3, "```") == 0;
    if (fence) {
      fenced = !fenced;
      continue;
    }
    lines.push_back({file, number, text, fenced});
  }
  return lines;
}

// README.md and every Markdown file under docs/, relative to the root, sorted.
std::vector<std::string> doc_files() {
  std::vector<std::string> files = {"README.md"};
  for (const auto& e : fs::recursive_directory_iterator(kRoot / "docs"))
    if (e.is_regular_file() && e.path().extension() == ".md") files.push_back(fs::relative(e.path(), kRoot).string());
  std::sort(files.begin() + 1, files.end());
  return files;
}

// ---- paths ----

// Does the relative path (with '*' wildcards and <placeholders>) exist under `base`?
bool pattern_exists(const fs::path& base, const std::string& rel) {
  std::vector<fs::path> current = {base};
  std::stringstream ss(rel);
  std::string part;
  while (std::getline(ss, part, '/')) {
    if (part.empty() || part == ".") continue;
    if (part.find('<') != std::string::npos) break;  // a placeholder: the folder so far must exist
    std::vector<fs::path> next;
    for (const fs::path& dir : current) {
      if (part.find('*') == std::string::npos) {
        std::error_code ec;
        if (fs::exists(dir / part, ec)) next.push_back(dir / part);
        continue;
      }
      std::error_code ec;
      if (!fs::is_directory(dir, ec)) continue;
      for (const auto& e : fs::directory_iterator(dir, ec))
        if (fnmatch(part.c_str(), e.path().filename().c_str(), 0) == 0) next.push_back(e.path());
    }
    current = std::move(next);
    if (current.empty()) return false;
  }
  return true;
}

bool is_top_folder(const std::string& first) {
  return std::find(std::begin(kTopFolders), std::end(kTopFolders), first) != std::end(kTopFolders);
}

// The places a token may refer to, or nothing when it is not a repository path.
std::vector<fs::path> candidate_bases(const std::string& token, bool code) {
  const std::string first = token.substr(0, token.find('/'));
  if (first.empty() || first == "." || first == "..") return {};
  if (is_top_folder(first)) return {kRoot};
  if (!code) return {};
  std::vector<fs::path> bases;
  for (const char* b : kShortBases) {
    std::error_code ec;
    if (fs::is_directory(kRoot / b / first, ec)) bases.push_back(kRoot / b);
  }
  return bases;
}

// Splits text into tokens made of path characters that contain a '/' (or end in ".md").
std::vector<std::string> path_tokens(const std::string& text) {
  auto path_char = [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.' || c == '/' || c == '*' || c == '<' ||
           c == '>' || c == '-' || c == '+';
  };
  std::vector<std::string> tokens;
  size_t i = 0;
  while (i < text.size()) {
    if (!path_char(text[i])) {
      ++i;
      continue;
    }
    size_t j = i;
    while (j < text.size() && path_char(text[j])) ++j;
    std::string t = text.substr(i, j - i);
    // A path never follows a letter-less run such as "-->" or "x.h/.cpp" (two files).
    while (!t.empty() && (t.back() == '.' || t.back() == '-' || t.back() == '>')) t.pop_back();
    if (i > 0 && (text[i - 1] == '$' || text[i - 1] == '~' || text[i - 1] == ':')) t.clear();  // $VAR/..., ~/..., a://b
    if (t.find('/') != std::string::npos || (t.size() > 3 && t.ends_with(".md"))) {
      const size_t split = t.find("/.");
      if (split != std::string::npos && split > 0 && t.find('/', split + 1) == std::string::npos &&
          t.rfind('.', split - 1) != std::string::npos) {
        // "scene.h/.cpp": the same name with two extensions.
        const std::string stem = t.substr(0, t.rfind('.', split - 1));
        tokens.push_back(t.substr(0, split));
        tokens.push_back(stem + t.substr(split + 1));
      } else {
        tokens.push_back(t);
      }
    }
    i = j;
  }
  return tokens;
}

// Code spans `...` of a line (backslash-escaped pipes of tables unescaped).
std::vector<std::string> code_spans(const std::string& text) {
  std::vector<std::string> spans;
  size_t i = 0;
  while ((i = text.find('`', i)) != std::string::npos) {
    size_t ticks = 0;
    while (i + ticks < text.size() && text[i + ticks] == '`') ++ticks;
    const std::string fence(ticks, '`');
    const size_t end = text.find(fence, i + ticks);
    if (end == std::string::npos) break;
    std::string s = text.substr(i + ticks, end - i - ticks);
    for (size_t p; (p = s.find("\\|")) != std::string::npos;) s.erase(p, 1);
    spans.push_back(s);
    i = end + ticks;
  }
  return spans;
}

// Markdown link targets [text](target) of a line, without #anchors; web links are skipped.
std::vector<std::string> link_targets(const std::string& text) {
  static const std::regex link(R"(\]\(([^)\s]+)\))");
  std::vector<std::string> targets;
  for (std::sregex_iterator it(text.begin(), text.end(), link), end; it != end; ++it) {
    std::string t = (*it)[1];
    if (t.find("://") != std::string::npos || t.starts_with("mailto:") || t.starts_with("#")) continue;
    t = t.substr(0, t.find('#'));
    if (!t.empty()) targets.push_back(t);
  }
  return targets;
}

void check_paths(const std::vector<DocLine>& lines, std::vector<Finding>* out) {
  for (const DocLine& l : lines) {
    const std::string where = l.file + ":" + std::to_string(l.number);
    std::set<std::string> reported;
    auto check = [&](const std::string& token, bool code) {
      if (reported.count(token)) return;
      if (token.starts_with("../")) {
        // Relative to the document; the only document that may name data outside the repository
        // is docs/testing.md (its section "Test data outside the repository").
        const fs::path resolved = (fs::path(l.file).parent_path() / token).lexically_normal();
        const bool outside = resolved.begin() != resolved.end() && *resolved.begin() == "..";
        if (outside && l.file != "docs/testing.md") {
          reported.insert(token);
          out->push_back({where, "points outside the repository: `" + token + "`"});
        } else if (!outside && !pattern_exists(kRoot, resolved.string())) {
          reported.insert(token);
          out->push_back({where, "names `" + token + "`, which does not exist in the repository"});
        }
        return;
      }
      if (token.find('/') == std::string::npos) {
        // A bare Markdown file name: at the root, in docs/, or next to the document.
        if (!token.ends_with(".md")) return;
        const fs::path here = (kRoot / l.file).parent_path();
        if (!fs::exists(kRoot / token) && !fs::exists(kRoot / "docs" / token) && !fs::exists(here / token)) {
          reported.insert(token);
          out->push_back({where, "names `" + token + "`, which is not a file of the repository"});
        }
        return;
      }
      const std::vector<fs::path> bases = candidate_bases(token, code);
      if (bases.empty()) return;
      for (const fs::path& b : bases)
        if (pattern_exists(b, token)) return;
      // A module named without its extension (`io/image_io` for image_io.h and .cpp).
      const std::string last = token.substr(token.rfind('/') + 1);
      if (!last.empty() && last.find('.') == std::string::npos)
        for (const fs::path& b : bases)
          if (pattern_exists(b, token + ".*")) return;
      reported.insert(token);
      out->push_back({where, "names `" + token + "`, which does not exist in the repository"});
    };
    // Prose: only unmistakable paths (starting at a top-level folder) and *.md names.
    for (const std::string& t : path_tokens(l.text)) check(t, l.fenced);
    for (const std::string& span : code_spans(l.text))
      for (const std::string& t : path_tokens(span)) check(t, true);
    for (const std::string& target : link_targets(l.text)) {
      const fs::path here = fs::path(l.file).parent_path();
      const fs::path resolved = (kRoot / here / target).lexically_normal();
      std::error_code ec;
      if (!fs::exists(resolved, ec) && !reported.count(target)) {
        reported.insert(target);
        out->push_back({where, "links to `" + target + "`, which does not exist"});
      }
    }
  }
}

// ---- options ----

std::set<std::string> option_tokens(const std::string& text) {
  static const std::regex option(R"((^|[^A-Za-z0-9_-])(--[A-Za-z0-9][A-Za-z0-9_-]*\*?))");
  std::set<std::string> out;
  for (std::sregex_iterator it(text.begin(), text.end(), option), end; it != end; ++it) out.insert((*it)[2]);
  return out;
}

bool other_tool_option(const std::string& opt) {
  if (kOtherToolsOptions.count(opt)) return true;
  for (const std::string& o : kOtherToolsOptions)
    if (o.back() == '_' && opt.starts_with(o)) return true;
  return false;
}

void check_options(const std::vector<DocLine>& lines, const std::set<std::string>& known, std::vector<Finding>* out) {
  for (const DocLine& l : lines) {
    for (const std::string& opt : option_tokens(l.text)) {
      if (other_tool_option(opt)) continue;
      bool ok = known.count(opt) > 0;
      if (!ok && opt.ends_with("-*")) {  // a family: --psf-*, --lt-*
        const std::string prefix = opt.substr(0, opt.size() - 1);
        for (const std::string& k : known) ok = ok || k.starts_with(prefix);
      }
      if (!ok)
        out->push_back({l.file + ":" + std::to_string(l.number),
                        "names the option `" + opt + "`, which no help text of pathspace lists"});
    }
  }
}

// ---- integrators ----

void check_integrators(const std::vector<DocLine>& lines, const std::set<std::string>& known,
                       std::vector<Finding>* out) {
  // -i NAME, --integrator NAME, --integrator=NAME; NAME may be a|b|c. Upper-case NAMEs are
  // placeholders.
  static const std::regex use(R"((^|[\s`(/])(-i|--integrator)[ =]([A-Za-z0-9_|-]+))");
  for (const DocLine& l : lines) {
    std::string text = l.text;
    for (size_t p; (p = text.find("\\|")) != std::string::npos;) text.erase(p, 1);
    for (std::sregex_iterator it(text.begin(), text.end(), use), end; it != end; ++it) {
      std::stringstream names((*it)[3].str());
      std::string name;
      while (std::getline(names, name, '|')) {
        if (name.empty() || std::none_of(name.begin(), name.end(), [](char c) { return std::islower(c); })) continue;
        if (!known.count(name))
          out->push_back({l.file + ":" + std::to_string(l.number),
                          "names the integrator `" + name + "`, which `pathspace info --integrators` does not list"});
      }
    }
  }
}

// ---- denials of registered things ----

// What `pathspace info --json` lists: {"integrators":[{"name":"pt",...}],"filters":[...],"devices":[...]}.
struct Registered {
  std::vector<std::string> integrators, filters, devices;
};

// What the pages call a registered thing besides its name, its option and "NAME KIND"; used only
// for names the registry lists.
const std::map<std::string, std::vector<std::string>> kDenialAliases = {
    {"pt", {"path tracer", "path tracing"}},
    {"lt", {"light tracer", "light tracing"}},
    {"bpt", {"bidirectional path tracer", "bidirectional path tracing"}},
    {"sppm", {"progressive photon mapping"}},
    {"pclt", {"pixel cache light tracing", "pixel cache light tracer"}},
    {"cuda", {"cuda backend", "gpu backend", "gpu path tracer", "cuda path tracer", "gpu filter"}},
};

// A registered thing and the lower-case texts that name it.
struct Subject {
  std::string label;  // "the device `cuda`"
  std::vector<std::string> names;
};

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

std::vector<Subject> subjects_of(const Registered& registered) {
  std::vector<Subject> out;
  auto add = [&out](const std::string& name, const std::string& kind, const std::vector<std::string>& kind_words,
                    const std::vector<std::string>& options) {
    const std::string n = lower(name);
    Subject s{"the " + kind + " `" + name + "`", {"`" + n + "`"}};
    for (const std::string& o : options) {
      s.names.push_back(o + " " + n);
      s.names.push_back(o + "=" + n);
    }
    for (const std::string& w : kind_words) s.names.push_back(n + " " + w);
    const auto alias = kDenialAliases.find(name);
    if (alias != kDenialAliases.end())
      for (const std::string& a : alias->second) s.names.push_back(lower(a));
    out.push_back(std::move(s));
  };
  // Devices first: "the GPU path tracer" is the CUDA backend more than it is `pt`.
  for (const std::string& d : registered.devices) add(d, "device", {"backend", "device backend"}, {"--device"});
  for (const std::string& f : registered.filters) add(f, "filter", {"filter"}, {"--filter"});
  for (const std::string& i : registered.integrators) add(i, "integrator", {"integrator"}, {"-i", "--integrator"});
  return out;
}

bool word_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// The [begin, end) ranges where `word` occurs in `text` as a whole word: a letter or digit at an
// end of `word` must not continue into the text around it.
std::vector<std::pair<size_t, size_t>> occurrences(const std::string& text, const std::string& word) {
  std::vector<std::pair<size_t, size_t>> out;
  if (word.empty()) return out;
  for (size_t p = text.find(word); p != std::string::npos; p = text.find(word, p + 1)) {
    const size_t e = p + word.size();
    const bool starts = p == 0 || !word_char(text[p - 1]) || !word_char(word.front());
    const bool ends = e == text.size() || !word_char(text[e]) || !word_char(word.back());
    if (starts && ends) out.emplace_back(p, e);
  }
  return out;
}

// The clauses of a line: split at a full stop, ';', parentheses and table cells.
std::vector<std::string> clauses(const std::string& text) {
  std::vector<std::string> out(1);
  for (size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    const bool full_stop = c == '.' && (i + 1 == text.size() || std::isspace(static_cast<unsigned char>(text[i + 1])));
    if (full_stop || c == ';' || c == '(' || c == ')' || c == '|')
      out.emplace_back();
    else
      out.back() += c;
  }
  return out;
}

// Phrases that deny what follows them within `reach` characters ("there is no CUDA backend", "not
// implemented yet: a wavefront GPU path tracer"), and phrases that deny what precedes them within 40
// characters ("the `consistent` filter does not exist").
struct DenyingLead {
  const char* text;
  size_t reach;
};
const DenyingLead kDenyingLeads[] = {{"there is no", 80},     {"there are no", 80},      {"not implemented", 80},
                                     {"not yet implemented", 80}, {"not built", 80}, {"not yet built", 80},
                                     {"no", 12}};
const char* const kDenyingTails[] = {"does not exist",      "doesn't exist",  "do not exist",      "is not implemented",
                                     "are not implemented", "is not yet implemented", "is not built", "are not built",
                                     "is not yet built",    "is not registered",      "is not available", "are not available"};
// A clause with one of these is conditional, or says where something runs, rather than that it does
// not exist: "without nvcc the CUDA backend is not built", "light tracing is not implemented on the GPU".
const char* const kQualifiers[] = {"without", "unless", " if ", "when ", "where ", "on the gpu", "on a gpu", "on the cpu",
                                   "on the device", "on gpus", "on cpus"};

// The label of the first subject a line denies, or "".
std::string denied_subject(const std::string& line, const std::vector<Subject>& subjects) {
  for (const std::string& clause : clauses(lower(line))) {
    const bool qualified = std::any_of(std::begin(kQualifiers), std::end(kQualifiers),
                                       [&clause](const char* q) { return clause.find(q) != std::string::npos; });
    if (qualified) continue;
    for (const Subject& s : subjects)
      for (const std::string& name : s.names)
        for (const std::pair<size_t, size_t>& at : occurrences(clause, name)) {
          for (const DenyingLead& lead : kDenyingLeads)
            for (const std::pair<size_t, size_t>& lead_at : occurrences(clause, lead.text))
              if (lead_at.second <= at.first && at.first - lead_at.second <= lead.reach) return s.label;
          const std::string after = clause.substr(at.second, 40);
          for (const char* tail : kDenyingTails)
            if (after.find(tail) != std::string::npos) return s.label;
        }
  }
  return "";
}

void check_denials(const std::vector<DocLine>& lines, const Registered& registered, std::vector<Finding>* out) {
  const std::vector<Subject> subjects = subjects_of(registered);
  for (const DocLine& l : lines) {
    if (l.fenced) continue;  // code, not a claim
    const std::string subject = denied_subject(l.text, subjects);
    if (!subject.empty())
      out->push_back({l.file + ":" + std::to_string(l.number),
                      "says that " + subject + " is missing, but `pathspace info --json` lists it"});
  }
}

// ---- the pathspace binary ----

std::set<std::string> help_options() {
  std::set<std::string> known;
  for (const char* args : kHelpCommands) {
    const Run r = run_pathspace(args);
    EXPECT_EQ(r.exit_code, 0) << "pathspace " << args << ":\n" << r.out;
    for (const std::string& o : option_tokens(r.out)) known.insert(o);
  }
  return known;
}

// The integrator names from `pathspace info --integrators --json`:
// {"integrators":[{"name":"pt",...},...],"filters":[...]}.
std::set<std::string> integrator_names() {
  std::set<std::string> names;
  const Run r = run_pathspace("info --integrators --json");
  EXPECT_EQ(r.exit_code, 0) << r.out;
  const nlohmann::json j = nlohmann::json::parse(r.out, nullptr, false);
  EXPECT_FALSE(j.is_discarded()) << "not JSON:\n" << r.out;
  if (j.is_discarded() || !j.contains("integrators")) return names;
  for (const auto& i : j["integrators"]) names.insert(i.at("name").get<std::string>());
  return names;
}

// The registered integrators, filters and devices from `pathspace info --json`.
Registered registered_things() {
  Registered registered;
  const Run r = run_pathspace("info --json");
  EXPECT_EQ(r.exit_code, 0) << r.out;
  const nlohmann::json j = nlohmann::json::parse(r.out, nullptr, false);
  EXPECT_FALSE(j.is_discarded()) << "not JSON:\n" << r.out;
  if (j.is_discarded()) return registered;
  const std::pair<const char*, std::vector<std::string>*> kinds[] = {
      {"integrators", &registered.integrators}, {"filters", &registered.filters}, {"devices", &registered.devices}};
  for (const auto& kind : kinds)
    if (j.contains(kind.first))
      for (const auto& entry : j.at(kind.first)) kind.second->push_back(entry.at("name").get<std::string>());
  return registered;
}

// ---- sections that the code cites ----

// Whether the page has a heading, or a bullet ("* **Determinism.** ...", "* Shading frame: ..."),
// that begins with the title.
bool page_has_section(const std::string& page, const std::string& title) {
  std::istringstream in(page);
  std::string line;
  while (std::getline(in, line)) {
    const size_t i = line.find_first_not_of(' ');
    if (i == std::string::npos) continue;
    std::string rest;
    if (line[i] == '#') {
      const size_t text = line.find_first_not_of("# ", i);
      if (text == std::string::npos) continue;
      rest = line.substr(text);
    } else if (line.compare(i, 2, "* ") == 0) {
      rest = line.substr(i + 2);
      if (rest.rfind("**", 0) == 0) rest = rest.substr(2);
    } else {
      continue;
    }
    if (rest.rfind(title, 0) == 0) return true;
  }
  return false;
}

void check_cited_sections(const std::vector<DocLine>& lines, std::vector<Finding>* out) {
  static const std::regex cite(R"re((docs/[A-Za-z0-9_/.-]+\.md)[,:]? ?\(?"([^"]+)")re");
  for (const DocLine& l : lines)
    for (std::sregex_iterator m(l.text.begin(), l.text.end(), cite), end; m != end; ++m) {
      const std::string page = (*m)[1], title = (*m)[2];
      const std::string where = l.file + ":" + std::to_string(l.number);
      if (!fs::is_regular_file(kRoot / page)) {
        out->push_back({where, "cites " + page + ", which does not exist"});
      } else if (!page_has_section(read_all(kRoot / page), title)) {
        out->push_back({where, "cites \"" + title + "\", which " + page + " has no heading or bullet for"});
      }
    }
}

// The lines of the sources, build files and scripts that may cite the docs.
std::vector<DocLine> all_code_lines() {
  static const std::set<std::string> kExtensions = {".h", ".cpp", ".cu", ".py", ".cmake", ".txt", ".sh"};
  std::vector<DocLine> lines;
  for (const char* folder : {"src", "apps", "studies", "bench", "tests", "python", "scripts", ".ci"}) {
    if (!fs::is_directory(kRoot / folder)) continue;
    for (const auto& e : fs::recursive_directory_iterator(kRoot / folder)) {
      if (!e.is_regular_file()) continue;
      const std::string ext = e.path().extension().string();
      const bool script = std::string(folder) == "scripts" || std::string(folder) == ".ci";
      if (!(script && ext.empty()) && !kExtensions.count(ext)) continue;
      if (ext == ".txt" && e.path().filename() != "CMakeLists.txt") continue;
      const std::vector<DocLine> l = split_lines(fs::relative(e.path(), kRoot).string(), read_all(e.path()));
      lines.insert(lines.end(), l.begin(), l.end());
    }
  }
  return lines;
}

std::vector<DocLine> all_doc_lines() {
  std::vector<DocLine> lines;
  for (const std::string& f : doc_files()) {
    const std::vector<DocLine> l = split_lines(f, read_all(kRoot / f));
    lines.insert(lines.end(), l.begin(), l.end());
  }
  return lines;
}

std::string report(const std::vector<Finding>& findings) {
  std::string s;
  for (const Finding& f : findings) s += f.where + ": " + f.what + "\n";
  return s;
}

TEST(Docs, NamedPathsExist) {
  std::vector<Finding> findings;
  check_paths(all_doc_lines(), &findings);
  EXPECT_TRUE(findings.empty()) << report(findings);
}

TEST(Docs, NamedOptionsAreAccepted) {
  const std::set<std::string> known = help_options();
  ASSERT_TRUE(known.count("--spp")) << "the help texts list no --spp: parsing them failed";
  std::vector<Finding> findings;
  check_options(all_doc_lines(), known, &findings);
  EXPECT_TRUE(findings.empty()) << report(findings);
}

TEST(Docs, NamedIntegratorsExist) {
  const std::set<std::string> known = integrator_names();
  ASSERT_TRUE(known.count("pt")) << "pathspace info --integrators --json lists no pt";
  std::vector<Finding> findings;
  check_integrators(all_doc_lines(), known, &findings);
  EXPECT_TRUE(findings.empty()) << report(findings);
}

TEST(Docs, RegisteredThingsAreNotDenied) {
  const Registered registered = registered_things();
  ASSERT_FALSE(registered.integrators.empty()) << "pathspace info --json lists no integrator";
  ASSERT_FALSE(registered.devices.empty()) << "pathspace info --json lists no device";
  std::vector<Finding> findings;
  check_denials(all_doc_lines(), registered, &findings);
  EXPECT_TRUE(findings.empty()) << report(findings);
}

TEST(Docs, CitedSectionsExist) {
  const std::vector<DocLine> lines = all_code_lines();
  ASSERT_GT(lines.size(), 10000u) << "the sources were not found under " << kRoot;
  std::vector<Finding> findings;
  check_cited_sections(lines, &findings);
  EXPECT_TRUE(findings.empty()) << report(findings);
}

// The section checker accepts headings and bullets that exist, and finds a missing page and a
// missing section, on made-up source lines.
TEST(DocsCheck, FindsCitedSectionsThatAreMissing) {
  // Built from pieces, so that the real check does not find these citations in this file.
  const std::string q = "\"", d = "docs/";
  const std::vector<DocLine> lines = split_lines(
      "src/made_up.h", "// " + d + "cli.md, " + q + "Checkpoints" + q + " and " + d + "hashed-filter.md " + q + "Determinism" + q +
                           "\n// (" + d + "conventions.md, " + q + "Shading frame" + q + ")\n" +
                           "// " + d + "no-such-page.md, " + q + "Anything" + q + "\n" +
                           "// " + d + "cli.md, " + q + "No such section" + q + "\n");
  std::vector<Finding> findings;
  check_cited_sections(lines, &findings);
  ASSERT_EQ(findings.size(), 2u) << report(findings);
  EXPECT_EQ(findings[0].where, "src/made_up.h:3");
  EXPECT_EQ(findings[1].where, "src/made_up.h:4");
}

// The checker finds what is missing (and accepts what exists), on a made-up document: three
// missing paths, a pointer outside the repository, an unknown .md file, an unknown option and two
// unknown integrators.
TEST(DocsCheck, FindsMissingThings) {
  const std::vector<DocLine> lines = split_lines("docs/made-up.md",
                                                 "Code in `integrators/pt/pt_kernel.h`, `src/pathspace/no_such_file.h` and\n"
                                                 "`integrators/pt/no_such_kernel.h`; see docs/no-such-page.md and [x](cli.md).\n"
                                                 "```\n"
                                                 "pathspace render -i pt --spp 4 --no-such-option\n"
                                                 "pathspace render --integrator=no-such-integrator --psf-*\n"
                                                 "```\n"
                                                 "`-i/--integrator pt|lt|nope`, `tests/fuzz/corpus/<format>/`, `pclt_options.*`.\n"
                                                 "Notes in ../shared/notes/performance.md and `cornell-variants.md`.\n"
                                                 "<!-- docs-test: off -->\n`integrators/toy/toy.h`, `-i toy --toy-scale 2`\n"
                                                 "<!-- docs-test: on -->\n");
  std::vector<Finding> paths, options, integrators;
  check_paths(lines, &paths);
  check_options(lines, {"--spp", "--integrator", "--psf-scale"}, &options);
  check_integrators(lines, {"pt", "lt"}, &integrators);
  EXPECT_EQ(paths.size(), 5u) << report(paths);
  ASSERT_EQ(options.size(), 1u) << report(options);
  EXPECT_NE(options[0].what.find("--no-such-option"), std::string::npos);
  EXPECT_EQ(options[0].where, "docs/made-up.md:4");
  ASSERT_EQ(integrators.size(), 2u) << report(integrators);
  EXPECT_NE(integrators[0].what.find("no-such-integrator"), std::string::npos);
  EXPECT_NE(integrators[1].what.find("nope"), std::string::npos);
}

// The denial checker finds the sentences that deny a registered thing, and leaves alone those that
// are conditional, about where something runs, about unregistered things, in code or switched off.
TEST(DocsCheck, FindsDenialsOfRegisteredThings) {
  const std::vector<DocLine> lines =
      split_lines("docs/made-up.md",
                  "There is no CUDA backend yet: the kernels only compile for the device.\n"           // 1: cuda
                  "Not implemented yet although the design names it: a wavefront GPU path tracer.\n"  // 2: cuda
                  "The `consistent` filter does not exist in this build.\n"                            // 3: consistent
                  "`-i bpt` is not implemented; use PT.\n"                                             // 4: bpt
                  "Without nvcc the CUDA backend is not built.\n"
                  "There is no toy integrator, and `-i toy` is not implemented.\n"
                  "Light tracing is not implemented on the GPU.\n"
                  "The hashed filter exists; no path is lost (`--filter hashed`).\n"
                  "| CLI no filter | `--filter consistent` |\n"
                  "```\n"
                  "there is no CUDA backend\n"
                  "```\n"
                  "<!-- docs-test: off -->\nThere is no `pt`.\n<!-- docs-test: on -->\n");
  const Registered registered{{"pt", "lt", "bpt"}, {"hashed", "consistent"}, {"cpu", "cuda"}};
  std::vector<Finding> findings;
  check_denials(lines, registered, &findings);
  ASSERT_EQ(findings.size(), 4u) << report(findings);
  const char* const expected[][2] = {{"docs/made-up.md:1", "`cuda`"},
                                     {"docs/made-up.md:2", "`cuda`"},
                                     {"docs/made-up.md:3", "`consistent`"},
                                     {"docs/made-up.md:4", "`bpt`"}};
  for (size_t i = 0; i < 4; ++i) {
    EXPECT_EQ(findings[i].where, expected[i][0]);
    EXPECT_NE(findings[i].what.find(expected[i][1]), std::string::npos) << findings[i].what;
  }
}

}  // namespace
