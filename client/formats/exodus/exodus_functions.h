#pragma once

#include <exodusII.h>
#include <netcdf.h>

#include "absl/status/status.h"

namespace getme::formats {

// Every Exodus II and netCDF function the reader and writer call, bound at run time from
// Debian's libexoIIv2c.so.5 (formats/runtime_library.h says why it is not linked). The netCDF
// ones come from the netCDF library the Exodus library itself loaded, so both work on the same
// open files. ex_open and ex_create are macros of exodusII.h for ex_open_int and ex_create_int,
// so `Exodus().ex_open(...)` still reaches the right member.
// clang-format off
#define GETME_EXODUS_FUNCTIONS(X)                                                                  \
  X(ex_close) X(ex_create_int) X(ex_get_attr) X(ex_get_attr_names) X(ex_get_block_param)           \
  X(ex_get_conn) X(ex_get_coord) X(ex_get_err) X(ex_get_id_map) X(ex_get_ids)                      \
  X(ex_get_init_ext) X(ex_get_names) X(ex_get_set) X(ex_get_set_dist_fact) X(ex_get_set_param)     \
  X(ex_get_side_set_node_list) X(ex_get_variable_param) X(ex_inquire_int) X(ex_open_int)           \
  X(ex_opts) X(ex_put_attr) X(ex_put_attr_names) X(ex_put_block) X(ex_put_conn) X(ex_put_coord)    \
  X(ex_put_coord_names) X(ex_put_id_map) X(ex_put_init_ext) X(ex_put_names) X(ex_put_set)          \
  X(ex_put_set_dist_fact) X(ex_put_set_param) X(ex_put_time) X(ex_put_var)                         \
  X(ex_put_variable_names) X(ex_put_variable_param) X(ex_set_int64_status)                         \
  X(ex_set_max_name_length) X(nc_close) X(nc_inq_att) X(nc_inq_attname) X(nc_inq_dimname)         \
  X(nc_inq_nvars) X(nc_inq_vardimid) X(nc_inq_varname) X(nc_inq_varnatts) X(nc_inq_varndims)       \
  X(nc_open) X(nc_strerror)
// clang-format on

struct ExodusFunctions {
#define GETME_EXODUS_FUNCTION_POINTER(name) decltype(&::name) name = nullptr;
  GETME_EXODUS_FUNCTIONS(GETME_EXODUS_FUNCTION_POINTER)
#undef GETME_EXODUS_FUNCTION_POINTER
};

// Loads the library once per process and binds every function; later calls return the first
// call's outcome. FailedPrecondition naming libexoIIv2c.so.5 and its package when it is missing.
absl::Status LoadExodusFunctions();

// The bound functions. Only after LoadExodusFunctions succeeded (ExodusFile's Open and Create
// call it): called before, it aborts, since every caller would crash on a null function anyway.
const ExodusFunctions& Exodus();

}  // namespace getme::formats
