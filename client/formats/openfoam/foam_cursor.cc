#include "formats/openfoam/foam_cursor.h"

#include <algorithm>
#include <charconv>
#include <system_error>

#include "absl/strings/str_cat.h"

namespace getme::formats {
namespace {

bool IsSpace(char c) {
  return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v';
}

bool EndsWord(char c) {
  return IsSpace(c) || c == '(' || c == ')' || c == '{' || c == '}' || c == ';' || c == '"';
}

// The token at `position` for messages: up to 20 characters of a word, or the one character.
std::string Shown(absl::string_view text, std::size_t position) {
  if (position >= text.size()) return "the end of the file";
  std::size_t end = position;
  while (end < text.size() && end - position < 20 && !EndsWord(text[end])) ++end;
  if (end == position) end = position + 1;
  std::string shown(text.substr(position, end - position));
  for (char& c : shown) {
    if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) >= 0x7f) c = '?';
  }
  return absl::StrCat("'", shown, "'");
}

}  // namespace

absl::Status FoamCursor::SkipSpace() {
  while (position_ < text_.size()) {
    const char c = text_[position_];
    if (IsSpace(c)) {
      ++position_;
    } else if (c == '/' && position_ + 1 < text_.size() && text_[position_ + 1] == '/') {
      const std::size_t end = text_.find('\n', position_);
      position_ = end == absl::string_view::npos ? text_.size() : end + 1;
    } else if (c == '/' && position_ + 1 < text_.size() && text_[position_ + 1] == '*') {
      const std::size_t end = text_.find("*/", position_ + 2);
      if (end == absl::string_view::npos) return Error("comment '/*' is never closed");
      position_ = end + 2;
    } else {
      break;
    }
  }
  return absl::OkStatus();
}

absl::Status FoamCursor::Expect(char punctuation, absl::string_view what) {
  if (absl::Status status = SkipSpace(); !status.ok()) return status;
  if (Peek() != punctuation) {
    return Error(absl::StrCat("expected '", std::string(1, punctuation), "' ", what, ", found ",
                              Shown(text_, position_)));
  }
  ++position_;
  return absl::OkStatus();
}

absl::StatusOr<std::string> FoamCursor::ReadWord(absl::string_view what) {
  if (absl::Status status = SkipSpace(); !status.ok()) return status;
  if (Peek() == '"') {
    const std::size_t end = text_.find('"', position_ + 1);
    if (end == absl::string_view::npos) return Error(absl::StrCat(what, ": string never closed"));
    std::string word(text_.substr(position_ + 1, end - position_ - 1));
    position_ = end + 1;
    return word;
  }
  const std::size_t begin = position_;
  while (position_ < text_.size() && !EndsWord(text_[position_])) ++position_;
  if (position_ == begin) {
    return Error(absl::StrCat("expected ", what, ", found ", Shown(text_, begin)));
  }
  return std::string(text_.substr(begin, position_ - begin));
}

absl::StatusOr<std::int64_t> FoamCursor::ReadInteger(absl::string_view what) {
  if (absl::Status status = SkipSpace(); !status.ok()) return status;
  std::int64_t value = 0;
  const char* begin = text_.data() + position_;
  const char* end = text_.data() + text_.size();
  const std::from_chars_result result = std::from_chars(begin, end, value);
  if (result.ec != std::errc() || (result.ptr < end && !EndsWord(*result.ptr))) {
    return Error(absl::StrCat("expected ", what, " (an integer), found ", Shown(text_, position_)));
  }
  position_ += static_cast<std::size_t>(result.ptr - begin);
  return value;
}

absl::StatusOr<double> FoamCursor::ReadReal(absl::string_view what) {
  if (absl::Status status = SkipSpace(); !status.ok()) return status;
  double value = 0;
  const char* begin = text_.data() + position_;
  const char* end = text_.data() + text_.size();
  // from_chars rejects a leading '+', which C's strtod (and so OpenFOAM) accepts.
  const char* start = begin < end && *begin == '+' ? begin + 1 : begin;
  const std::from_chars_result result = std::from_chars(start, end, value);
  if (result.ec != std::errc() || (result.ptr < end && !EndsWord(*result.ptr))) {
    return Error(absl::StrCat("expected ", what, " (a number), found ", Shown(text_, position_)));
  }
  position_ += static_cast<std::size_t>(result.ptr - begin);
  return value;
}

absl::StatusOr<absl::string_view> FoamCursor::ReadBytes(std::size_t count, absl::string_view what) {
  if (count > text_.size() - position_) {
    return Error(absl::StrCat(what, ": needs ", count, " bytes, but only ",
                              text_.size() - position_, " remain"));
  }
  const absl::string_view bytes = text_.substr(position_, count);
  position_ += count;
  return bytes;
}

absl::Status FoamCursor::ErrorAt(std::size_t position, absl::string_view message) const {
  position = std::min(position, text_.size());
  if (binary_) {
    return absl::InvalidArgumentError(absl::StrCat(file_name_, ": byte ", position, ": ", message));
  }
  const std::int64_t line =
      1 + std::count(text_.begin(), text_.begin() + static_cast<std::ptrdiff_t>(position), '\n');
  return absl::InvalidArgumentError(absl::StrCat(file_name_, ": line ", line, ": ", message));
}

}  // namespace getme::formats
