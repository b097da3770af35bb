#pragma once

#include <cstdint>
#include <optional>

#include "absl/strings/string_view.h"

namespace getme::formats {

// The numeric data types a VTK legacy file may name for POINTS and attribute arrays, spelled as
// the file spells them so a file is written back with the type it was read with.
enum class VtkDataType : std::uint8_t {
  kBit,
  kUnsignedChar,
  kChar,
  kSignedChar,
  kUnsignedShort,
  kShort,
  kUnsignedInt,
  kInt,
  kUnsignedLong,
  kLong,
  kIdType,
  kInt8,
  kUInt8,
  kInt16,
  kUInt16,
  kInt32,
  kUInt32,
  kInt64,
  kUInt64,
  kFloat,
  kDouble,
};

struct VtkDataTypeInfo {
  absl::string_view name;  // as written in the file, e.g. "unsigned_char", "vtktypeint64"
  // Bytes per value in BINARY files (big-endian). Legacy VTK writes vtkIdType as a 32-bit int
  // and long as the writer's native long, which is 64 bits on every LP64 system VTK ships for.
  // 0 for bit: bits are packed eight to a byte, most significant bit first.
  int binary_size;
  bool is_integer;
  bool is_signed;
  std::int64_t min;   // integer types only
  std::uint64_t max;  // integer types only
};

const VtkDataTypeInfo& DataTypeInfo(VtkDataType type);
// Case-insensitive, as VTK's reader; nullopt for names that are not numeric types
// (string, utf8_string, variant, or garbage).
std::optional<VtkDataType> ParseDataTypeName(absl::string_view name);

inline bool IsIntegerType(VtkDataType type) { return DataTypeInfo(type).is_integer; }

}  // namespace getme::formats
