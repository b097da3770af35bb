#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "absl/strings/string_view.h"
#include "formats/vtk_data_type.h"

namespace getme::formats {

// How a file stores its numbers: as text, or as binary values.
enum class Encoding { kAscii, kBinary };

// One numeric array: `components` values per tuple, tuple-major. Floating-point types keep their
// values in `reals`, integer types (and bit) in `integers`; the other vector stays empty.
// 64-bit unsigned values above INT64_MAX are stored bit-cast (AsDouble undoes that).
//
// Values read from an ASCII file are kept as the parsed doubles even when the file says float,
// so "9.49" stays 9.49 rather than the float nearest to it; the writer writes a float array as
// double when a value would not survive the narrowing (see vtk_writer.h).
struct DataArray {
  std::string name;  // decoded (VTK writes spaces and '%' in names as %20, %25)
  VtkDataType type = VtkDataType::kDouble;
  int components = 1;
  std::vector<double> reals;
  std::vector<std::int64_t> integers;

  std::int64_t value_count() const {
    return static_cast<std::int64_t>(IsIntegerType(type) ? integers.size() : reals.size());
  }
  std::int64_t tuple_count() const { return components > 0 ? value_count() / components : 0; }
  double AsDouble(std::int64_t index) const;
};

// The kinds of POINT_DATA / CELL_DATA sections of the legacy format.
enum class VtkAttributeKind {
  kScalars,             // SCALARS name type [components] + LOOKUP_TABLE name
  kColorScalars,        // COLOR_SCALARS name components (ASCII floats in [0,1], BINARY bytes)
  kLookupTable,         // LOOKUP_TABLE name size: RGBA, same encoding as COLOR_SCALARS
  kVectors,             // VECTORS name type
  kNormals,             // NORMALS name type
  kTextureCoordinates,  // TEXTURE_COORDINATES name dim type
  kTensors,             // TENSORS name type (9 components)
  kGlobalIds,           // GLOBAL_IDS name type
  kField,               // FIELD name count, then `count` named arrays
};

// One section of POINT_DATA / CELL_DATA / dataset FIELD data, in file order. Every kind but
// kField has exactly one array, whose name is the section's name; kField has any number.
struct VtkAttribute {
  VtkAttributeKind kind = VtkAttributeKind::kScalars;
  std::string name;          // the array name, or the FIELD's own name
  std::string lookup_table;  // kScalars only: the LOOKUP_TABLE line's name ("default")
  std::vector<DataArray> arrays;
};

// Cells in file order: cell i has type types[i] and the point ids
// connectivity[offsets[i] .. offsets[i+1]) in VTK's node order.
struct GridCells {
  std::vector<std::int64_t> offsets{0};
  std::vector<std::int64_t> connectivity;
  std::vector<std::uint8_t> types;

  std::int64_t size() const { return static_cast<std::int64_t>(types.size()); }
  std::int64_t node_count(std::int64_t cell) const { return offsets[cell + 1] - offsets[cell]; }
  const std::int64_t* nodes(std::int64_t cell) const { return connectivity.data() + offsets[cell]; }
  void Add(int type, const std::vector<std::int64_t>& nodes);
};

// The neutral grid of the file formats: every reader (VTK legacy, VTU, Gmsh, MEDIT) produces
// one and every writer consumes one (formats/mesh_document.h). Its model is VTK's unstructured
// grid, the richest of the four, so a VTK legacy DATASET UNSTRUCTURED_GRID file is held with
// everything needed to write it back; version, title and encoding are those of VTK legacy.
struct UnstructuredGrid {
  // "# vtk DataFile Version major.minor". From 5.1 on, CELLS are written as OFFSETS and
  // CONNECTIVITY arrays; before, as "n id0 id1 …" rows.
  int version_major = 3;
  int version_minor = 0;
  std::string title;
  Encoding encoding = Encoding::kAscii;
  std::vector<VtkAttribute> field_data;  // dataset-level FIELD sections
  DataArray points;                      // 3 components
  GridCells cells;
  std::vector<VtkAttribute> point_data;
  std::vector<VtkAttribute> cell_data;

  std::int64_t point_count() const { return points.tuple_count(); }
  bool uses_offsets_layout() const {
    return version_major > 5 || (version_major == 5 && version_minor >= 1);
  }
};

// The first array called `name` in any section of `attributes` (SCALARS, FIELD, …), or null.
const DataArray* FindArray(const std::vector<VtkAttribute>& attributes, absl::string_view name);
DataArray* FindArray(std::vector<VtkAttribute>& attributes, absl::string_view name);

absl::string_view AttributeKindKeyword(VtkAttributeKind kind);

}  // namespace getme::formats
