#pragma once

#include <charconv>
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
  // The next token if it is a plain decimal integer within [min, max]: an optional sign and at
  // most 18 digits, ending at whitespace or the end of the input. Anything else (another form,
  // a value out of range, the end of the input) gives nullopt with the token not consumed, so
  // NextToken then returns it and the caller reports it as before. Reading the digits while
  // finding the token's end, without NextToken's view and from_chars, took a fifth off reading
  // cub_wedge_like.vtk, whose CELLS are most of its tokens (docs/benchmarks.md, "Before the
  // engine, and two set-up costs in it").
  std::optional<std::int64_t> NextPlainInteger(std::int64_t min, std::int64_t max) {
    SkipWhitespace();
    std::size_t at = pos_;
    const std::size_t size = bytes_.size();
    if (at >= size) return std::nullopt;
    const bool negative = bytes_[at] == '-';
    // An unsigned type refuses a sign even on zero (from_chars), so "-0" takes the slow path.
    if (negative && min >= 0) return std::nullopt;
    if (negative || bytes_[at] == '+') ++at;
    const std::size_t digits_start = at;
    std::int64_t magnitude = 0;
    while (at < size && at - digits_start < kPlainDigits) {
      const auto digit = static_cast<unsigned>(bytes_[at]) - '0';
      if (digit > 9) break;
      magnitude = magnitude * 10 + static_cast<std::int64_t>(digit);
      ++at;
    }
    if (at == digits_start || (at < size && !IsSpace(bytes_[at]))) return std::nullopt;
    const std::int64_t value = negative ? -magnitude : magnitude;
    if (value < min || value > max) return std::nullopt;
    last_line_ = line_;
    last_offset_ = static_cast<std::int64_t>(pos_);
    pos_ = at;
    return value;
  }

  // The next token if std::from_chars reads all of it as a double (no leading '+'), the same
  // value ParseRealToken gives; otherwise nullopt with the token not consumed, as above.
  std::optional<double> NextPlainReal() {
    SkipWhitespace();
    const std::size_t size = bytes_.size();
    if (pos_ >= size || bytes_[pos_] == '+') return std::nullopt;
    std::size_t end = pos_;
    while (end < size && !IsSpace(bytes_[end])) ++end;
    double value = 0.0;
    const char* first = bytes_.data() + pos_;
    const char* last = bytes_.data() + end;
    const auto [ptr, ec] = std::from_chars(first, last, value);
    if (ec != std::errc() || ptr != last) return std::nullopt;
    last_line_ = line_;
    last_offset_ = static_cast<std::int64_t>(pos_);
    pos_ = end;
    return value;
  }

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
  // Digits of a plain integer: 18 cannot overflow std::int64_t.
  static constexpr std::size_t kPlainDigits = 18;

  static bool IsSpace(char c) {
    return c == ' ' || c == '\n' || c == '\r' || c == '\t' || c == '\f' || c == '\v';
  }
  void SkipWhitespace() {
    while (pos_ < bytes_.size() && IsSpace(bytes_[pos_])) {
      if (bytes_[pos_] == '\n') ++line_;
      ++pos_;
    }
  }

  absl::string_view bytes_;
  std::size_t pos_ = 0;
  std::int64_t line_ = 1;
  bool binary_ = false;
  std::int64_t last_line_ = 1;
  std::int64_t last_offset_ = 0;
};

}  // namespace getme::formats
