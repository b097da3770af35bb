#pragma once

#include <string>

#include "absl/status/statusor.h"
#include "formats/mesh_document.h"

namespace getme::formats {

// Serializes document.grid as a VTK XML UnstructuredGrid file (version 1.0, LittleEndian,
// header_type UInt64), one <Piece>. options.encoding kAscii writes every array as ascii text;
// kBinary writes base64 inside each DataArray (vtu_layout kInline) or raw bytes in one
// <AppendedData encoding="raw"> section (kAppended), compressed in zlib blocks if vtu_compress.
//
// Numbers as the legacy writer prints them: the shortest decimal that reads back bit-identical,
// float arrays as Float32 when every value is exactly a float and as Float64 otherwise. Types
// keep their width and signedness (vtu_names.h; bit becomes UInt8). Cells are written as Int64
// connectivity and offsets and UInt8 types.
//
// Attribute roles: the first Scalars (or COLOR_SCALARS), Vectors, Normals, Tensors,
// TextureCoordinates and GlobalIds section of the point and cell data that fits the role is
// named by <PointData Scalars="…" …> so ParaView colours by it; all other arrays are plain
// DataArrays in section order (ParseVtu reads them back as vtu_reader.h says). Lookup tables,
// whose length is not the point or cell count, go to the grid's <FieldData>; the lookup table a
// SCALARS section names is not kept (it reads back as "default"). The grid's title and
// legacy version have no place in the format and are not written.
//
// InvalidArgument if the grid is inconsistent (as SerializeVtk checks: array lengths, node ids,
// integers outside their type, unnamed arrays), holds a polyhedron (VTK XML keeps its faces in
// arrays the model does not have), or an array name holds a control character XML cannot carry.
absl::StatusOr<std::string> SerializeVtu(const MeshDocument& document, const WriteOptions& options);

}  // namespace getme::formats
