#pragma once

#include <cstdint>

#include "absl/status/status.h"
#include "absl/strings/string_view.h"
#include "formats/unstructured_grid.h"

namespace getme::formats {

// What both VTK writers (legacy and XML) check before writing an array: at least one
// component, values in the vector its type uses, whole tuples, `tuples` of them (-1: any
// number), every integer within its type. InvalidArgument prefixed with `what`.
absl::Status CheckArrayForWriting(const DataArray& array, std::int64_t tuples,
                                  absl::string_view what);

// The type an array is written with: a float array holding a value that is not exactly a float
// (parsed from ASCII, or smoothed coordinates) is promoted to double so no digit is lost.
VtkDataType TypeKeepingEveryValue(const DataArray& array);

}  // namespace getme::formats
