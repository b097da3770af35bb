#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>

#include "absl/strings/string_view.h"

namespace getme::formats::medit {

// A token of an ASCII MEDIT file and the 1-based line it starts on.
struct Token {
  absl::string_view text;
  std::int64_t line = 0;
};

// Splits an ASCII MEDIT file into whitespace-separated tokens. The format is free: line breaks
// mean nothing (libMeshb reads with fscanf), and a token starting with '#' comments out the rest
// of its line, as in libMeshb's keyword scan. Never reads past the end.
class Scanner {
 public:
  explicit Scanner(absl::string_view bytes) : bytes_(bytes) {}

  // The next token; nullopt at the end of the input.
  std::optional<Token> Next();
  // The line the cursor is on (for "the file ends at line …").
  std::int64_t line() const { return line_; }
  std::size_t remaining() const { return bytes_.size() - pos_; }

 private:
  absl::string_view bytes_;
  std::size_t pos_ = 0;
  std::int64_t line_ = 1;
};

}  // namespace getme::formats::medit
