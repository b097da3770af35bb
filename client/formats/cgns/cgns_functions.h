#pragma once

#include <cgnslib.h>

#include "absl/status/status.h"

namespace getme::formats::cgns {

// Every CGNS mid-level library function the reader and writer call, bound at run time from
// Debian's libcgns.so.3.4 (formats/runtime_library.h says why it is not linked).
// clang-format off
#define GETME_CGNS_FUNCTIONS(X)                                                                    \
  X(cg_ElementDataSize) X(cg_ElementTypeName) X(cg_GridLocationName) X(cg_PointSetTypeName)        \
  X(cg_ZoneTypeName) X(cg_base_read) X(cg_base_write) X(cg_boco_gridlocation_read)                 \
  X(cg_boco_gridlocation_write) X(cg_boco_info) X(cg_boco_read) X(cg_boco_write) X(cg_close)       \
  X(cg_coord_info) X(cg_coord_read) X(cg_coord_write) X(cg_elements_read) X(cg_fambc_read)         \
  X(cg_fambc_write) X(cg_family_read) X(cg_family_write) X(cg_famname_read) X(cg_famname_write)    \
  X(cg_field_info) X(cg_field_read) X(cg_field_write) X(cg_get_error) X(cg_get_file_type)          \
  X(cg_goto) X(cg_nbases) X(cg_nbocos) X(cg_ncoords) X(cg_nfamilies) X(cg_nfields)                 \
  X(cg_nsections) X(cg_nsols) X(cg_nzones) X(cg_open) X(cg_poly_elements_read)                     \
  X(cg_poly_section_write) X(cg_section_read) X(cg_section_write) X(cg_set_file_type)              \
  X(cg_sol_info) X(cg_sol_write) X(cg_zone_read) X(cg_zone_type) X(cg_zone_write)
// clang-format on

struct CgnsFunctions {
#define GETME_CGNS_FUNCTION_POINTER(name) decltype(&::name) name = nullptr;
  GETME_CGNS_FUNCTIONS(GETME_CGNS_FUNCTION_POINTER)
#undef GETME_CGNS_FUNCTION_POINTER
};

// Loads the library once per process and binds every function; later calls return the first
// call's outcome. FailedPrecondition naming libcgns.so.3.4 and its package when it is missing.
absl::Status LoadCgnsFunctions();

// The bound functions. Only after LoadCgnsFunctions succeeded (OpenFile::Open calls it): called
// before, it aborts, since every caller would crash on a null function anyway.
const CgnsFunctions& Cgns();

}  // namespace getme::formats::cgns
