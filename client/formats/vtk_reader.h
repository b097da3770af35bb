#pragma once

#include <string>

#include "absl/status/statusor.h"
#include "absl/strings/string_view.h"
#include "formats/unstructured_grid.h"

namespace getme::formats {

// Parses a VTK legacy file (ASCII or big-endian BINARY, DATASET UNSTRUCTURED_GRID, cells either
// as the classic "CELLS n size" rows or, from file version 5.1 on, as OFFSETS/CONNECTIVITY
// arrays). Malformed input of any kind gives InvalidArgument naming the line (ASCII) or byte
// offset (BINARY) and what was expected there; the parser never reads out of bounds and never
// allocates more than the input could hold.
//
// Checked: header, DATASET type, section keywords and their counts, every number against its
// declared type, node ids against the point count, the node count of every fixed-size cell
// type, and that POINT_DATA / CELL_DATA sizes match the points and cells. Not kept: METADATA
// blocks (VTK 9 writes component names there), which are skipped.
absl::StatusOr<UnstructuredGrid> ParseVtk(absl::string_view bytes);

// Reads and parses `path`. NotFound / PermissionDenied etc. name the path; parse errors are
// prefixed with it.
absl::StatusOr<UnstructuredGrid> ReadVtkFile(const std::string& path);

}  // namespace getme::formats
