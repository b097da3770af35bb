#include "formats/vtk_data_type.h"

#include <array>
#include <limits>

#include "absl/strings/match.h"

namespace getme::formats {
namespace {

template <typename T>
constexpr VtkDataTypeInfo IntegerInfo(absl::string_view name, int binary_size) {
  return {name,
          binary_size,
          true,
          std::numeric_limits<T>::is_signed,
          static_cast<std::int64_t>(std::numeric_limits<T>::min()),
          static_cast<std::uint64_t>(std::numeric_limits<T>::max())};
}

// Indexed by VtkDataType.
constexpr std::array<VtkDataTypeInfo, 21> kInfos = {{
    {"bit", 0, true, false, 0, 1},
    IntegerInfo<std::uint8_t>("unsigned_char", 1),
    IntegerInfo<std::int8_t>("char", 1),
    IntegerInfo<std::int8_t>("signed_char", 1),
    IntegerInfo<std::uint16_t>("unsigned_short", 2),
    IntegerInfo<std::int16_t>("short", 2),
    IntegerInfo<std::uint32_t>("unsigned_int", 4),
    IntegerInfo<std::int32_t>("int", 4),
    IntegerInfo<std::uint64_t>("unsigned_long", 8),
    IntegerInfo<std::int64_t>("long", 8),
    IntegerInfo<std::int32_t>("vtkIdType", 4),
    IntegerInfo<std::int8_t>("vtktypeint8", 1),
    IntegerInfo<std::uint8_t>("vtktypeuint8", 1),
    IntegerInfo<std::int16_t>("vtktypeint16", 2),
    IntegerInfo<std::uint16_t>("vtktypeuint16", 2),
    IntegerInfo<std::int32_t>("vtktypeint32", 4),
    IntegerInfo<std::uint32_t>("vtktypeuint32", 4),
    IntegerInfo<std::int64_t>("vtktypeint64", 8),
    IntegerInfo<std::uint64_t>("vtktypeuint64", 8),
    {"float", 4, false, true, 0, 0},
    {"double", 8, false, true, 0, 0},
}};

static_assert(kInfos.size() == static_cast<std::size_t>(VtkDataType::kDouble) + 1);

}  // namespace

const VtkDataTypeInfo& DataTypeInfo(VtkDataType type) {
  return kInfos[static_cast<std::size_t>(type)];
}

std::optional<VtkDataType> ParseDataTypeName(absl::string_view name) {
  for (std::size_t i = 0; i < kInfos.size(); ++i) {
    if (absl::EqualsIgnoreCase(name, kInfos[i].name)) return static_cast<VtkDataType>(i);
  }
  return std::nullopt;
}

}  // namespace getme::formats
