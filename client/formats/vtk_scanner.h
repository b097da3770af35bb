#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "absl/strings/string_view.h"

namespace getme::formats {

// Where something is in a VTK legacy file: a 1-based line number in ASCII files (and in the
// text header of every file), a 0-based byte offset in BINARY files, where line numbers stop
// meaning anything once raw data has been skipped.
struct VtkLocation {
  bool is_byte_offset = false;
  std::int64_t value = 0;
  std::string ToString() const;  // "line 12" / "byte 345"
};

// A cursor over the bytes of a VTK legacy file. Keyword lines are read whole (so BINARY data
// can start right after the newline that ends them); ASCII values are read token by token.
// Never reads past the end: every accessor reports running out instead.
class VtkScanner {
 public:
  explicit VtkScanner(absl::string_view bytes) : bytes_(bytes) {}

  // After the header: BINARY files report byte offsets instead of line numbers.
  void set_binary(bool binary) { binary_ = binary; }
  bool binary() const { return binary_; }

  // The next raw line without its "\n" or "\r\n"; nullopt at the end of the input.
  std::optional<absl::string_view> ReadRawLine();
  // Skips blank lines and returns the whitespace-separated words of the next line, consuming
  // its newline; an empty vector at the end of the input. `location()` is then the line start.
  std::vector<absl::string_view> ReadKeywordLine();
  // The next whitespace-delimited token (ASCII values); nullopt at the end of the input.
  std::optional<absl::string_view> NextToken();
  // The next `count` raw bytes (BINARY values); nullopt, consuming nothing, if fewer remain.
  std::optional<absl::string_view> TakeBytes(std::size_t count);

  // Where the last line, token or byte block returned started.
  VtkLocation location() const { return {binary_, binary_ ? last_offset_ : last_line_}; }
  // Where the cursor is now (for "the file ends at …").
  VtkLocation here() const { return {binary_, binary_ ? static_cast<std::int64_t>(pos_) : line_}; }
  std::size_t remaining() const { return bytes_.size() - pos_; }

  // A saved position, to look at the next keyword line and step back if it is not the one
  // expected (SCALARS' optional LOOKUP_TABLE line).
  struct State {
    std::size_t pos;
    std::int64_t line;
  };
  State Save() const { return {pos_, line_}; }
  void Restore(State state) {
    pos_ = state.pos;
    line_ = state.line;
  }

 private:
  void SkipWhitespace();

  absl::string_view bytes_;
  std::size_t pos_ = 0;
  std::int64_t line_ = 1;
  bool binary_ = false;
  std::int64_t last_line_ = 1;
  std::int64_t last_offset_ = 0;
};

}  // namespace getme::formats
