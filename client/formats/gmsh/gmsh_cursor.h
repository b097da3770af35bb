#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "absl/strings/string_view.h"

namespace getme::formats {

// A cursor over the bytes of a Gmsh MSH file. Section headers and the text parts of binary
// sections are read as lines; ASCII values token by token (Gmsh reads them with fscanf, so line
// breaks between values do not matter); binary values as fixed-size little- or big-endian
// numbers. Never reads past the end: every accessor reports running out instead.
class GmshCursor {
 public:
  explicit GmshCursor(absl::string_view bytes) : bytes_(bytes) {}

  // Binary files: values are raw bytes, little-endian unless `big_endian` (a file written on a
  // big-endian machine), `size_t_size` the bytes of a size_t (4.1's data-size). Binary files
  // report byte offsets: line numbers mean nothing once raw data has been read.
  void SetBinary(bool big_endian, int size_t_size) {
    binary_ = true;
    big_endian_ = big_endian;
    size_t_size_ = size_t_size;
  }
  bool binary() const { return binary_; }

  // The next line without its "\n" or "\r\n"; nullopt at the end of the input.
  std::optional<absl::string_view> ReadLine();
  // Skips blank lines (and whitespace) and returns the next line, trimmed; nullopt at the end.
  std::optional<absl::string_view> ReadNonBlankLine();
  // The next whitespace-delimited token; nullopt at the end of the input.
  std::optional<absl::string_view> NextToken();
  // The next `count` raw bytes; nullopt, consuming nothing, if fewer remain.
  std::optional<absl::string_view> Take(std::size_t count);
  std::optional<std::int32_t> TakeInt32();
  std::optional<std::uint64_t> TakeSize();  // size_t_size bytes
  std::optional<double> TakeDouble();
  int size_t_size() const { return size_t_size_; }

  // The body of a section up to (not including) the line "$End<name>", which is consumed; nullopt
  // if there is no such line.
  std::optional<absl::string_view> TakeUntilEnd(absl::string_view name);

  // Where the last line, token or value returned started: "line 12" or "byte 345".
  std::string Where() const;
  // Where the cursor is now (for "the file ends …").
  std::string Here() const;
  std::size_t remaining() const { return bytes_.size() - pos_; }
  std::size_t size() const { return bytes_.size(); }

 private:
  void Mark() {
    last_offset_ = pos_;
    last_line_ = line_;
  }

  absl::string_view bytes_;
  std::size_t pos_ = 0;
  std::int64_t line_ = 1;
  bool binary_ = false;
  bool big_endian_ = false;
  int size_t_size_ = 8;
  std::size_t last_offset_ = 0;
  std::int64_t last_line_ = 1;
};

}  // namespace getme::formats
