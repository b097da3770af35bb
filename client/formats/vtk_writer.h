#pragma once

#include <string>

#include "absl/status/status.h"
#include "absl/status/statusor.h"
#include "formats/unstructured_grid.h"

namespace getme::formats {

// Serializes `file` as a VTK legacy file in `encoding` (file.encoding is not consulted), with
// the file's version, title, sections and attribute order. Cells are written as OFFSETS /
// CONNECTIVITY (vtktypeint64) arrays for version 5.1 and later, as classic "CELLS n size" rows
// otherwise.
//
// Numbers: doubles as the shortest decimal that reads back bit-identical (std::to_chars; never
// longer than %.17g), float arrays as floats when every value is exactly a float and as double
// otherwise (values parsed from an ASCII "float" file, or smoothed coordinates, must not lose
// digits). BINARY is big-endian, with vtkIdType as 32-bit and long as 64-bit, as VTK writes
// them. COLOR_SCALARS / LOOKUP_TABLE values are bytes in BINARY (value · 255, rounded), as VTK
// defines; that is the one lossy conversion.
//
// Fails with InvalidArgument if the model is inconsistent: wrong array lengths, node ids out of
// range, integers outside their type, a title with a line break, an unnamed array.
//
// `threads` > 1 formats the numbers of large ASCII sections on that many threads
// (parallel_text.h); the bytes are the same for every thread count.
absl::StatusOr<std::string> SerializeVtk(const UnstructuredGrid& file, Encoding encoding,
                                         int threads = 1);

// Writes atomically: to a temporary file beside `path`, renamed over it once complete.
absl::Status WriteVtkFile(const std::string& path, const UnstructuredGrid& file, Encoding encoding);
inline absl::Status WriteVtkFile(const std::string& path, const UnstructuredGrid& file) {
  return WriteVtkFile(path, file, file.encoding);
}

}  // namespace getme::formats
