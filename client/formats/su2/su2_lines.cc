#include "formats/su2/su2_lines.h"

#include "absl/strings/ascii.h"

namespace getme::formats::su2 {

std::optional<Line> Lines::Next() {
  if (peeked_.has_value()) {
    std::optional<Line> line = peeked_;
    peeked_.reset();
    return line;
  }
  while (pos_ < bytes_.size()) {
    const std::size_t start = pos_;
    std::size_t end = bytes_.find('\n', pos_);
    if (end == absl::string_view::npos) end = bytes_.size();
    pos_ = end < bytes_.size() ? end + 1 : end;
    Line line;
    line.number = line_++;
    line.start = start;
    absl::string_view text = bytes_.substr(start, end - start);
    const std::size_t comment = text.find('%');
    if (comment != absl::string_view::npos) text = text.substr(0, comment);
    line.text = absl::StripAsciiWhitespace(text);
    if (!line.text.empty()) return line;
  }
  return std::nullopt;
}

std::optional<Line> Lines::Peek() {
  if (!peeked_.has_value()) peeked_ = Next();
  return peeked_;
}

}  // namespace getme::formats::su2
