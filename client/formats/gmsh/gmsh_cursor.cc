#include "formats/gmsh/gmsh_cursor.h"

#include <bit>

#include "absl/strings/ascii.h"
#include "absl/strings/str_cat.h"

namespace getme::formats {
namespace {

bool IsSpace(char c) {
  return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f';
}

// The unsigned value of `size` bytes, little- or big-endian.
std::uint64_t Decode(const char* bytes, int size, bool big_endian) {
  std::uint64_t value = 0;
  for (int i = 0; i < size; ++i) {
    const int from = big_endian ? i : size - 1 - i;
    value = (value << 8) | static_cast<unsigned char>(bytes[from]);
  }
  return value;
}

}  // namespace

std::optional<absl::string_view> GmshCursor::ReadLine() {
  if (pos_ >= bytes_.size()) return std::nullopt;
  Mark();
  const std::size_t end = bytes_.find('\n', pos_);
  absl::string_view line;
  if (end == absl::string_view::npos) {
    line = bytes_.substr(pos_);
    pos_ = bytes_.size();
  } else {
    line = bytes_.substr(pos_, end - pos_);
    pos_ = end + 1;
    ++line_;
  }
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  return line;
}

std::optional<absl::string_view> GmshCursor::ReadNonBlankLine() {
  for (;;) {
    const std::optional<absl::string_view> line = ReadLine();
    if (!line) return std::nullopt;
    const absl::string_view trimmed = absl::StripAsciiWhitespace(*line);
    if (!trimmed.empty()) return trimmed;
  }
}

std::optional<absl::string_view> GmshCursor::NextToken() {
  while (pos_ < bytes_.size() && IsSpace(bytes_[pos_])) {
    if (bytes_[pos_] == '\n') ++line_;
    ++pos_;
  }
  if (pos_ >= bytes_.size()) return std::nullopt;
  Mark();
  const std::size_t start = pos_;
  while (pos_ < bytes_.size() && !IsSpace(bytes_[pos_])) ++pos_;
  return bytes_.substr(start, pos_ - start);
}

std::optional<absl::string_view> GmshCursor::Take(std::size_t count) {
  if (count > remaining()) return std::nullopt;
  Mark();
  const absl::string_view taken = bytes_.substr(pos_, count);
  pos_ += count;
  return taken;
}

std::optional<std::int32_t> GmshCursor::TakeInt32() {
  const std::optional<absl::string_view> bytes = Take(4);
  if (!bytes) return std::nullopt;
  return std::bit_cast<std::int32_t>(
      static_cast<std::uint32_t>(Decode(bytes->data(), 4, big_endian_)));
}

std::optional<std::uint64_t> GmshCursor::TakeSize() {
  if (size_t_size_ == 4) {
    const std::optional<std::int32_t> value = TakeInt32();
    if (!value) return std::nullopt;
    return std::bit_cast<std::uint32_t>(*value);
  }
  const std::optional<absl::string_view> bytes = Take(8);
  if (!bytes) return std::nullopt;
  return Decode(bytes->data(), 8, big_endian_);
}

std::optional<double> GmshCursor::TakeDouble() {
  const std::optional<absl::string_view> bytes = Take(8);
  if (!bytes) return std::nullopt;
  return std::bit_cast<double>(Decode(bytes->data(), 8, big_endian_));
}

std::optional<absl::string_view> GmshCursor::TakeUntilEnd(absl::string_view name) {
  const std::string marker = absl::StrCat("$End", name);
  std::size_t from = pos_;
  for (;;) {
    const std::size_t at = bytes_.find(marker, from);
    if (at == absl::string_view::npos) return std::nullopt;
    const std::size_t after = at + marker.size();
    const bool line_start = at == pos_ || bytes_[at - 1] == '\n';
    const bool line_end = after == bytes_.size() || IsSpace(bytes_[after]);
    if (line_start && line_end) {
      const absl::string_view body = bytes_.substr(pos_, at - pos_);
      for (char c : body) line_ += c == '\n' ? 1 : 0;
      pos_ = at;
      ReadLine();
      return body;
    }
    from = at + 1;
  }
}

std::string GmshCursor::Where() const {
  return binary_ ? absl::StrCat("byte ", last_offset_) : absl::StrCat("line ", last_line_);
}

std::string GmshCursor::Here() const {
  return binary_ ? absl::StrCat("byte ", pos_) : absl::StrCat("line ", line_);
}

}  // namespace getme::formats
