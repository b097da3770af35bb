#pragma once

#include "absl/status/statusor.h"
#include "absl/strings/string_view.h"
#include "formats/mesh_document.h"

namespace getme::formats {

// Parses a VTK XML UnstructuredGrid file (.vtu): VTKFile version 0.1, 1.0 and 2.x, byte_order
// LittleEndian or BigEndian, header_type UInt32 or UInt64, DataArrays in format "ascii",
// "binary" (base64) or "appended" (an <AppendedData> section, encoding "raw" or "base64"),
// uncompressed or compressed with vtkZLibDataCompressor. The result has format kVtkXml and
// `as_read` set to the file's encoding (kAscii only if every array is ascii), layout (kAppended
// if any array is appended) and compression.
//
// The grid: points, cells (connectivity / offsets / types), point, cell and field data, with
// the data types of vtu_names.h. Several <Piece>s are merged into one grid, in file order
// (node ids of later pieces offset by the points before them); their point and cell data must
// have the same arrays. The roles <PointData Scalars="a" Vectors="b" …> assigns become the
// legacy section kinds (Scalars, Vectors, Normals, Tensors, TCoords, GlobalIds); arrays without
// a role become later SCALARS sections when they follow the active scalars and have 1–4
// components (the legacy format makes only the first SCALARS active, so they stay plain arrays
// for VTK), and otherwise FIELD "FieldData" sections, which is how VTK's legacy writer stores
// plain arrays. Either way they write back to .vtu as plain arrays again. Grid-level
// <FieldData> becomes one FIELD "FieldData" section. The file has no title; the grid's title is
// empty and its legacy version the default.
//
// Malformed input gives InvalidArgument naming the line of the XML element and the array:
// counts against NumberOfPoints / NumberOfCells / NumberOfTuples, offsets (non-decreasing,
// ending at the connectivity length), node ids, the node count of fixed-size cell types,
// unknown cell type codes, polyhedra (faces / faceoffsets: unsupported), base64 and zlib
// corruption, appended offsets and sizes beyond the data, unsupported types (String, Bit) and
// compressors (vtkLZ4DataCompressor, vtkLZMADataCompressor). Never reads out of bounds and never
// allocates more than the input could hold.
absl::StatusOr<MeshDocument> ParseVtu(absl::string_view bytes);

}  // namespace getme::formats
