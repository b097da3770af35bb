#include "formats/unstructured_grid.h"

#include <bit>

namespace getme::formats {

double DataArray::AsDouble(std::int64_t index) const {
  if (!IsIntegerType(type)) return reals[index];
  const std::int64_t value = integers[index];
  if (!DataTypeInfo(type).is_signed && value < 0) {
    return static_cast<double>(std::bit_cast<std::uint64_t>(value));
  }
  return static_cast<double>(value);
}

void GridCells::Add(int type, const std::vector<std::int64_t>& nodes) {
  types.push_back(static_cast<std::uint8_t>(type));
  connectivity.insert(connectivity.end(), nodes.begin(), nodes.end());
  offsets.push_back(static_cast<std::int64_t>(connectivity.size()));
}

const DataArray* FindArray(const std::vector<VtkAttribute>& attributes, absl::string_view name) {
  for (const VtkAttribute& attribute : attributes) {
    for (const DataArray& array : attribute.arrays) {
      if (array.name == name) return &array;
    }
  }
  return nullptr;
}

DataArray* FindArray(std::vector<VtkAttribute>& attributes, absl::string_view name) {
  const auto& const_attributes = attributes;
  return const_cast<DataArray*>(FindArray(const_attributes, name));
}

absl::string_view AttributeKindKeyword(VtkAttributeKind kind) {
  switch (kind) {
    case VtkAttributeKind::kScalars:
      return "SCALARS";
    case VtkAttributeKind::kColorScalars:
      return "COLOR_SCALARS";
    case VtkAttributeKind::kLookupTable:
      return "LOOKUP_TABLE";
    case VtkAttributeKind::kVectors:
      return "VECTORS";
    case VtkAttributeKind::kNormals:
      return "NORMALS";
    case VtkAttributeKind::kTextureCoordinates:
      return "TEXTURE_COORDINATES";
    case VtkAttributeKind::kTensors:
      return "TENSORS";
    case VtkAttributeKind::kGlobalIds:
      return "GLOBAL_IDS";
    case VtkAttributeKind::kField:
      return "FIELD";
  }
  return "FIELD";
}

}  // namespace getme::formats
