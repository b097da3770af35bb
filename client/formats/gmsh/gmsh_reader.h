#pragma once

#include "absl/status/statusor.h"
#include "absl/strings/string_view.h"
#include "formats/mesh_document.h"

namespace getme::formats {

// Parses a Gmsh MSH file, version 2.2 (2.0 and 2.1 read as 2.2) or 4.1, ASCII or binary (either
// byte order; 4.1 with a 4- or 8-byte size_t as its $MeshFormat data-size says).
//
// grid: points = nodes in file order; cells = every element in file order as VTK cells (points
// 15 → vertex, 1 line, 2 triangle, 3 quad, 4 tetra, 5 hexahedron, 6 prism → wedge with VTK's
// mirrored node order, 7 pyramid); cell data "gmsh:physical" and "gmsh:geometrical" (Int32,
// meshio's names: a 4.1 element's entity's first physical tag, 0 if none, and its entity tag;
// a 2.2 element's first two tags); each $NodeData / $ElementData section becomes one double
// array named by its first string tag. A later section with a name already taken (another time
// step, another partition) gets " [step N]" (or " [k]") appended so every array keeps its own
// values; points or cells a section does not list hold NaN, except in an array named "fixed",
// where they hold 0 (not fixed). An $ElementNodeData section whose every entry has one value at
// all nodes of its element (how the writer stores 2.2 cell arrays, gmsh_writer.h) is read as a
// cell array too; any other $ElementNodeData is kept verbatim. document.gmsh holds everything
// else needed to write the file back (see GmshExtras).
//
// Second- and higher-order elements are rejected, naming the element and its type: getme
// smooths linear elements only.
//
// Malformed input gives InvalidArgument naming the line (ASCII) or the byte offset (binary)
// and the section, the node or element tag involved and what was expected. The parser never
// reads out of bounds and never reserves more than the remaining bytes could hold.
absl::StatusOr<MeshDocument> ParseGmsh(absl::string_view bytes);

}  // namespace getme::formats
