#include "formats/vtu/vtu_names.h"

#include <array>

namespace getme::formats::vtu {
namespace {

struct XmlType {
  absl::string_view name;
  VtkDataType type;
};

constexpr std::array<XmlType, 10> kXmlTypes = {{
    {"Int8", VtkDataType::kChar},
    {"UInt8", VtkDataType::kUnsignedChar},
    {"Int16", VtkDataType::kShort},
    {"UInt16", VtkDataType::kUnsignedShort},
    {"Int32", VtkDataType::kInt},
    {"UInt32", VtkDataType::kUnsignedInt},
    {"Int64", VtkDataType::kLong},
    {"UInt64", VtkDataType::kUnsignedLong},
    {"Float32", VtkDataType::kFloat},
    {"Float64", VtkDataType::kDouble},
}};

constexpr std::array<XmlRole, 6> kRoles = {{
    {VtkAttributeKind::kScalars, "Scalars"},
    {VtkAttributeKind::kVectors, "Vectors"},
    {VtkAttributeKind::kNormals, "Normals"},
    {VtkAttributeKind::kTensors, "Tensors"},
    {VtkAttributeKind::kTextureCoordinates, "TCoords"},
    {VtkAttributeKind::kGlobalIds, "GlobalIds"},
}};

}  // namespace

std::optional<VtkDataType> ParseXmlTypeName(absl::string_view name) {
  for (const XmlType& type : kXmlTypes) {
    if (type.name == name) return type.type;
  }
  return std::nullopt;
}

VtkDataType XmlStorageType(VtkDataType type) {
  switch (type) {
    case VtkDataType::kBit:
    case VtkDataType::kUnsignedChar:
    case VtkDataType::kUInt8:
      return VtkDataType::kUnsignedChar;
    case VtkDataType::kChar:
    case VtkDataType::kSignedChar:
    case VtkDataType::kInt8:
      return VtkDataType::kChar;
    case VtkDataType::kUnsignedShort:
    case VtkDataType::kUInt16:
      return VtkDataType::kUnsignedShort;
    case VtkDataType::kShort:
    case VtkDataType::kInt16:
      return VtkDataType::kShort;
    case VtkDataType::kUnsignedInt:
    case VtkDataType::kUInt32:
      return VtkDataType::kUnsignedInt;
    case VtkDataType::kInt:
    case VtkDataType::kInt32:
    case VtkDataType::kIdType:
      return VtkDataType::kInt;
    case VtkDataType::kUnsignedLong:
    case VtkDataType::kUInt64:
      return VtkDataType::kUnsignedLong;
    case VtkDataType::kLong:
    case VtkDataType::kInt64:
      return VtkDataType::kLong;
    case VtkDataType::kFloat:
      return VtkDataType::kFloat;
    case VtkDataType::kDouble:
      return VtkDataType::kDouble;
  }
  return VtkDataType::kDouble;
}

absl::string_view XmlTypeName(VtkDataType type) {
  const VtkDataType storage = XmlStorageType(type);
  for (const XmlType& xml_type : kXmlTypes) {
    if (xml_type.type == storage) return xml_type.name;
  }
  return "Float64";
}

absl::string_view XmlTypeNames() {
  return "Int8, UInt8, Int16, UInt16, Int32, UInt32, Int64, UInt64, Float32, Float64";
}

std::span<const XmlRole> XmlRoles() { return kRoles; }

bool RoleFits(VtkAttributeKind kind, int components) {
  switch (kind) {
    case VtkAttributeKind::kScalars:
      return components >= 1 && components <= 4;
    case VtkAttributeKind::kVectors:
    case VtkAttributeKind::kNormals:
      return components == 3;
    case VtkAttributeKind::kTensors:
      return components == 9;
    case VtkAttributeKind::kTextureCoordinates:
      return components >= 1 && components <= 3;
    case VtkAttributeKind::kGlobalIds:
      return components == 1;
    default:
      return false;
  }
}

}  // namespace getme::formats::vtu
