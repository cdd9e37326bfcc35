// pbrt-v4 tokenizer (see pbrt_tokenizer.h). Unterminated strings are syntax errors with location.
#include "pathspace/io/pbrt/pbrt_tokenizer.h"

namespace pathspace::pbrt {

std::string Token::unquoted() const {
  std::string s;
  for (size_t i = 1; i + 1 < text.size(); ++i) {
    char c = text[i];
    if (c == '\\' && i + 2 < text.size()) {
      c = text[++i];
      switch (c) {
        case 'n': c = '\n'; break;
        case 't': c = '\t'; break;
        case 'r': c = '\r'; break;
        default: break;  // \\ and \" give the character itself
      }
    }
    s += c;
  }
  return s;
}

Tokenizer::Tokenizer(const std::string& source, std::string file_name) : src_(source), file_(std::move(file_name)) {}

Token Tokenizer::peek() {
  if (!has_peeked_) {
    peeked_ = scan();
    has_peeked_ = true;
  }
  return peeked_;
}

Token Tokenizer::next() {
  if (has_peeked_) {
    has_peeked_ = false;
    return peeked_;
  }
  return scan();
}

Token Tokenizer::scan() {
  auto advance = [&]() {
    if (src_[pos_] == '\n') {
      ++line_;
      column_ = 1;
    } else {
      ++column_;
    }
    ++pos_;
  };
  for (;;) {
    while (pos_ < src_.size() && (src_[pos_] == ' ' || src_[pos_] == '\t' || src_[pos_] == '\n' || src_[pos_] == '\r')) advance();
    if (pos_ < src_.size() && src_[pos_] == '#') {
      while (pos_ < src_.size() && src_[pos_] != '\n') advance();
      continue;
    }
    break;
  }
  Token t;
  t.loc = FileLoc{file_, line_, column_};
  if (pos_ >= src_.size()) return t;
  const size_t start = pos_;
  const char c = src_[pos_];
  if (c == '[' || c == ']') {
    advance();
  } else if (c == '"') {
    advance();
    while (pos_ < src_.size() && src_[pos_] != '"') {
      if (src_[pos_] == '\n') throw Error(t.loc, "unterminated string (newline inside quotes)");
      if (src_[pos_] == '\\' && pos_ + 1 < src_.size()) advance();
      advance();
    }
    if (pos_ >= src_.size()) throw Error(t.loc, "unterminated string at end of file");
    advance();
  } else {
    while (pos_ < src_.size()) {
      const char d = src_[pos_];
      if (d == ' ' || d == '\t' || d == '\n' || d == '\r' || d == '"' || d == '[' || d == ']' || d == '#') break;
      advance();
    }
  }
  t.text = std::string_view(src_).substr(start, pos_ - start);
  return t;
}

}  // namespace pathspace::pbrt
