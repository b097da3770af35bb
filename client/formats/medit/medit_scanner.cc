#include "formats/medit/medit_scanner.h"

namespace getme::formats::medit {
namespace {

bool IsSpace(char c) {
  return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v';
}

}  // namespace

std::optional<Token> Scanner::Next() {
  while (pos_ < bytes_.size()) {
    const char c = bytes_[pos_];
    if (c == '\n') {
      ++line_;
      ++pos_;
    } else if (IsSpace(c)) {
      ++pos_;
    } else if (c == '#') {
      while (pos_ < bytes_.size() && bytes_[pos_] != '\n') ++pos_;
    } else {
      break;
    }
  }
  if (pos_ == bytes_.size()) return std::nullopt;
  const std::size_t start = pos_;
  while (pos_ < bytes_.size() && !IsSpace(bytes_[pos_])) ++pos_;
  return Token{bytes_.substr(start, pos_ - start), line_};
}

}  // namespace getme::formats::medit
