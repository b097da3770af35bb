#pragma once

#include <string>

#include "absl/status/status.h"

namespace getme::formats {

// Checks the header of a netCDF-3 file (classic "CDF\x01", 64-bit offset "CDF\x02", 64-bit data
// "CDF\x05"; netCDF File Format Specification, "The Format in Detail") against the size of the
// file before the netCDF library parses it: every list count, name length and attribute length
// must fit in the bytes that are left, no name may be longer than NC_MAX_NAME, every dimension id
// must exist, and no dimension may be longer than the file could hold values for.
//
// Why: netCDF 4.9.0 allocates what the header declares before reading it; a 4 KB file whose
// header claims 10^9 attributes makes it allocate gigabytes (found by formats_exodus_test's
// corruption test, killed by the OOM killer at 24 GB). Files that are not netCDF-3 (HDF5-based
// netCDF-4, anything else) pass unchecked: the libraries refuse or read them as they do.
// InvalidArgument naming the header part and the byte offset.
absl::Status CheckNetcdfClassicHeader(const std::string& path);

}  // namespace getme::formats
