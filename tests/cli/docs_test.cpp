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
//    `pathspace info --integrators --json`.
// Lines between <!-- docs-test: off --> and <!-- docs-test: on --> (a worked example of code that
// does not exist) are not checked.
// A failure names the document, the line and the missing thing. The checker itself is tested on a
// made-up document (DocsCheck.FindsMissingThings), so it cannot pass by finding nothing.
#include <fnmatch.h>
#include <sys/wait.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>
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
const char* const kHelpCommands[] = {"--help", "render --help", "info --help", "compare --help", "study --help",
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

}  // namespace
