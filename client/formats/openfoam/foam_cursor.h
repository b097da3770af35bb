#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include "absl/status/status.h"
#include "absl/status/statusor.h"
#include "absl/strings/string_view.h"

namespace getme::formats {

// A read position in one OpenFOAM file (FoamFile dictionary syntax, OpenFOAM User Guide §4.2
// "Basic input/output file format"): skips white space and C++ comments between tokens, reads
// the tokens the polyMesh files use, and reads the raw bytes of a binary list block.
//
// Errors name the file and where: "line N" in ASCII files, "byte N" (0-based offset in the
// decompressed file) once the file is known to be binary, since its lines mean nothing there.
class FoamCursor {
 public:
  FoamCursor(absl::string_view file_name, absl::string_view text)
      : file_name_(file_name), text_(text) {}

  // Whether positions are reported as byte offsets (binary files) rather than lines.
  void set_binary(bool binary) { binary_ = binary; }

  std::size_t position() const { return position_; }
  void set_position(std::size_t position) { position_ = position; }
  absl::string_view text() const { return text_; }
  absl::string_view file_name() const { return file_name_; }

  // Skips white space, "// …" and "/* … */" comments. InvalidArgument for an unclosed "/*".
  absl::Status SkipSpace();
  // After SkipSpace: whether the text is exhausted, and the next character ('\0' at the end).
  bool AtEnd() const { return position_ >= text_.size(); }
  char Peek() const { return AtEnd() ? '\0' : text_[position_]; }

  // Skips space, then requires `punctuation` ('(', ')', '{', '}', ';') and steps over it.
  absl::Status Expect(char punctuation, absl::string_view what);
  // Skips space, then a word (keyword, patch name, number as text) or a "quoted string" without
  // its quotes: everything up to white space or one of ( ) { } ; "
  absl::StatusOr<std::string> ReadWord(absl::string_view what);
  // Skips space, then a non-negative or negative integer / a real number (C locale).
  absl::StatusOr<std::int64_t> ReadInteger(absl::string_view what);
  absl::StatusOr<double> ReadReal(absl::string_view what);
  // `count` raw bytes from the current position, without skipping anything: the contents of a
  // binary block, which begin right after its '('. InvalidArgument when fewer remain.
  absl::StatusOr<absl::string_view> ReadBytes(std::size_t count, absl::string_view what);

  // "points: line 12: <message>" / "faces: byte 4096: <message>" at the current position.
  absl::Status Error(absl::string_view message) const { return ErrorAt(position_, message); }
  absl::Status ErrorAt(std::size_t position, absl::string_view message) const;

 private:
  absl::string_view file_name_;
  absl::string_view text_;
  std::size_t position_ = 0;
  bool binary_ = false;
};

}  // namespace getme::formats
