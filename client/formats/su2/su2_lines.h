#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>

#include "absl/strings/string_view.h"

namespace getme::formats::su2 {

// A line of an SU2 mesh file with what it holds: the text before any '%' comment, without
// surrounding whitespace, and its 1-based number.
struct Line {
  absl::string_view text;
  std::int64_t number = 0;
  std::size_t start = 0;  // byte offset of the line in the file
};

// Walks an SU2 native mesh file line by line. The format is line-based (SU2's reader takes one
// element or point per line), spacing within a line is free (spaces or tabs), and '%' starts a
// comment that runs to the end of the line (SU2 Mesh File documentation, "SU2 Native Format").
// Lines that hold nothing but a comment or whitespace are skipped. Never reads past the end.
class Lines {
 public:
  explicit Lines(absl::string_view bytes) : bytes_(bytes) {}

  // The next line with content; nullopt at the end of the input.
  std::optional<Line> Next();
  // The next line with content, without consuming it.
  std::optional<Line> Peek();
  // The number of the last line read (for "the file ends at line …").
  std::int64_t last_line() const { return line_ - 1; }
  std::size_t remaining() const { return bytes_.size() - pos_; }

 private:
  absl::string_view bytes_;
  std::size_t pos_ = 0;
  std::int64_t line_ = 1;
  std::optional<Line> peeked_;
};

}  // namespace getme::formats::su2
