#include "formats/vtk_array_checks.h"

#include <cmath>

#include "absl/strings/str_cat.h"
#include "formats/vtk_values.h"

namespace getme::formats {

absl::Status CheckArrayForWriting(const DataArray& array, std::int64_t tuples,
                                  absl::string_view what) {
  if (array.components < 1) {
    return absl::InvalidArgumentError(
        absl::StrCat(what, ": the component count is ", array.components, "; expected >= 1"));
  }
  const bool integer = IsIntegerType(array.type);
  if ((integer && !array.reals.empty()) || (!integer && !array.integers.empty())) {
    return absl::InvalidArgumentError(absl::StrCat(
        what, ": values are stored in the wrong vector for type ", DataTypeInfo(array.type).name));
  }
  if (array.value_count() % array.components != 0) {
    return absl::InvalidArgumentError(absl::StrCat(what, ": ", array.value_count(),
                                                   " values are not a whole number of ",
                                                   array.components, "-component tuples"));
  }
  if (tuples >= 0 && array.tuple_count() != tuples) {
    return absl::InvalidArgumentError(
        absl::StrCat(what, ": has ", array.tuple_count(), " tuples; expected ", tuples));
  }
  for (std::size_t i = 0; i < array.integers.size(); ++i) {
    const bool fits = array.type == VtkDataType::kBit
                          ? (array.integers[i] == 0 || array.integers[i] == 1)
                          : IntegerFits(array.integers[i], array.type);
    if (!fits) {
      return absl::InvalidArgumentError(absl::StrCat(what, ": value ", i, " (", array.integers[i],
                                                     ") does not fit type ",
                                                     DataTypeInfo(array.type).name));
    }
  }
  return absl::OkStatus();
}

VtkDataType TypeKeepingEveryValue(const DataArray& array) {
  if (array.type != VtkDataType::kFloat) return array.type;
  for (const double value : array.reals) {
    if (std::isnan(value)) continue;
    if (static_cast<double>(static_cast<float>(value)) != value) return VtkDataType::kDouble;
  }
  return VtkDataType::kFloat;
}

}  // namespace getme::formats
