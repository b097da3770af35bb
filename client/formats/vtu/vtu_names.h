#pragma once

#include <optional>
#include <span>

#include "absl/strings/string_view.h"
#include "formats/unstructured_grid.h"
#include "formats/vtk_data_type.h"

namespace getme::formats::vtu {

// VTK XML names a DataArray's type by width ("Int32", "Float64"); the model spells types as the
// legacy format does. Each XML type maps to one legacy type, the one VTK's legacy writer uses
// for it (Int32 → int, Int64 → long, …), so a .vtu written as .vtk names types VTK and meshio
// both read.
std::optional<VtkDataType> ParseXmlTypeName(absl::string_view name);
// The legacy type an array of `type` is stored as in XML: same width and signedness. bit (0/1
// values) becomes unsigned_char: VTK XML's "Bit" type is unknown to meshio and most readers.
VtkDataType XmlStorageType(VtkDataType type);
// The XML name of XmlStorageType(type).
absl::string_view XmlTypeName(VtkDataType type);
// "Int8, UInt8, …, Float64", for error messages.
absl::string_view XmlTypeNames();

// The attribute roles a <PointData> / <CellData> element assigns to its arrays by name
// (Scalars="temperature"), as the legacy format's section kinds.
struct XmlRole {
  VtkAttributeKind kind;
  absl::string_view attribute;  // "Scalars", "Vectors", …
};
std::span<const XmlRole> XmlRoles();
// Whether an array of `components` can carry the role: VTK's legacy writer and ParaView expect
// 3 components for vectors and normals, 9 for tensors, 1–3 for texture coordinates, 1 for ids.
bool RoleFits(VtkAttributeKind kind, int components);

}  // namespace getme::formats::vtu
