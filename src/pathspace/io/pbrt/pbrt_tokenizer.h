// Tokenizer for the pbrt-v4 scene format: quoted strings, brackets, bare words and numbers, with
// '#' comments skipped. Every token carries its file:line:column so parse errors and warnings can
// point at the exact place (pathspace::FileLoc).
#pragma once

#include <string>
#include <string_view>

#include "pathspace/base/error.h"

namespace pathspace::pbrt {

struct Token {
  std::string_view text;  // quoted strings keep their quotes; empty at the end of the input
  FileLoc loc;
  bool is_string() const { return text.size() >= 2 && text.front() == '"'; }
  bool is_open() const { return text == "["; }
  bool is_close() const { return text == "]"; }
  bool at_end() const { return text.empty(); }
  // A quoted string's contents (escape sequences resolved).
  std::string unquoted() const;
};

class Tokenizer {
 public:
  // `source` must outlive the tokenizer (tokens are views into it).
  Tokenizer(const std::string& source, std::string file_name);
  Token next();
  Token peek();
  const std::string& file() const { return file_; }

 private:
  Token scan();
  const std::string& src_;
  std::string file_;
  size_t pos_ = 0;
  int line_ = 1, column_ = 1;
  bool has_peeked_ = false;
  Token peeked_;
};

}  // namespace pathspace::pbrt
