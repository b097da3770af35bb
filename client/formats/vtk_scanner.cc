#include "formats/vtk_scanner.h"

#include "absl/strings/str_cat.h"

namespace getme::formats {
std::string VtkLocation::ToString() const {
  return absl::StrCat(is_byte_offset ? "byte " : "line ", value);
}

std::optional<absl::string_view> VtkScanner::ReadRawLine() {
  if (pos_ >= bytes_.size()) return std::nullopt;
  last_line_ = line_;
  last_offset_ = static_cast<std::int64_t>(pos_);
  const std::size_t end = bytes_.find('\n', pos_);
  absl::string_view line = bytes_.substr(pos_, end == absl::string_view::npos ? end : end - pos_);
  if (end == absl::string_view::npos) {
    pos_ = bytes_.size();
  } else {
    pos_ = end + 1;
    ++line_;
  }
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  return line;
}

std::vector<absl::string_view> VtkScanner::ReadKeywordLine() {
  SkipWhitespace();
  std::vector<absl::string_view> words;
  const std::optional<absl::string_view> line = ReadRawLine();
  if (!line) return words;
  std::size_t i = 0;
  while (i < line->size()) {
    while (i < line->size() && IsSpace((*line)[i])) ++i;
    const std::size_t start = i;
    while (i < line->size() && !IsSpace((*line)[i])) ++i;
    if (i > start) words.push_back(line->substr(start, i - start));
  }
  return words;
}

std::optional<absl::string_view> VtkScanner::NextToken() {
  SkipWhitespace();
  if (pos_ >= bytes_.size()) return std::nullopt;
  last_line_ = line_;
  last_offset_ = static_cast<std::int64_t>(pos_);
  const std::size_t start = pos_;
  while (pos_ < bytes_.size() && !IsSpace(bytes_[pos_])) ++pos_;
  return bytes_.substr(start, pos_ - start);
}

std::optional<absl::string_view> VtkScanner::TakeBytes(std::size_t count) {
  if (count > remaining()) return std::nullopt;
  last_line_ = line_;
  last_offset_ = static_cast<std::int64_t>(pos_);
  const absl::string_view block = bytes_.substr(pos_, count);
  pos_ += count;
  return block;
}

}  // namespace getme::formats
