#include "formats/exodus/exodus_library.h"

#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <system_error>
#include <vector>

#include "absl/strings/ascii.h"
#include "absl/strings/str_cat.h"
#include "absl/strings/str_join.h"
#include "absl/strings/str_replace.h"
#include "formats/exodus/exodus_functions.h"
#include "formats/exodus/exodus_netcdf_header.h"

namespace getme::formats {
namespace {

// ex_err codes of the library itself (exodusII.h, "Exodus error return codes"); everything
// else it reports is a netCDF status or an errno value, which nc_strerror explains.
bool IsExodusOwnCode(int code) { return code >= EX_MEMFAIL || code <= EX_MSG; }

// The Exodus library reads these attributes into a single value on its stack (ex_large_model,
// ex_open) without asking netCDF how many values they have; a file giving more overflows its
// stack (found by formats_exodus_test's corruption test: "file_size" with 1,000 values). So the
// file's header is checked with netCDF itself first.
constexpr const char* kScalarAttributes[] = {
    "file_size",   "floating_point_word_size", "version",     "api_version",
    "api version", "maximum_name_length",      "int64_status"};

// Text attributes the library copies into fixed buffers: the title (MAX_LINE_LENGTH) and the
// element type of each block (MAX_STR_LENGTH).
struct TextLimit {
  const char* name;
  std::size_t longest;
};
constexpr TextLimit kTextAttributes[] = {{"title", MAX_LINE_LENGTH}, {"elem_type", MAX_STR_LENGTH}};

absl::Status CheckAttributes(int ncid, int variable, absl::string_view owner) {
  int count = 0;
  if (Exodus().nc_inq_varnatts(ncid, variable, &count) != NC_NOERR) return absl::OkStatus();
  for (int k = 0; k < count; ++k) {
    char name[NC_MAX_NAME + 1] = {};
    nc_type type = NC_NAT;
    std::size_t length = 0;
    if (Exodus().nc_inq_attname(ncid, variable, k, name) != NC_NOERR ||
        Exodus().nc_inq_att(ncid, variable, name, &type, &length) != NC_NOERR) {
      continue;
    }
    for (const char* scalar : kScalarAttributes) {
      if (std::strcmp(name, scalar) == 0 && (length != 1 || type == NC_CHAR || type == NC_STRING)) {
        return absl::InvalidArgumentError(
            absl::StrCat(owner, " attribute '", name, "' has ", length,
                         type == NC_CHAR || type == NC_STRING ? " characters" : " values",
                         "; Exodus II stores one number there"));
      }
    }
    for (const TextLimit& text : kTextAttributes) {
      if (std::strcmp(name, text.name) == 0 && (type != NC_CHAR || length > text.longest + 1)) {
        return absl::InvalidArgumentError(absl::StrCat(
            owner, " attribute '", name, "' is not text of at most ", text.longest, " characters"));
      }
    }
  }
  return absl::OkStatus();
}

// The Exodus library takes the size of a block or set from dimensions it looks up by name
// (num_el_in_blk3, num_nod_per_el3), and getme sizes its buffers from the same numbers; but it
// reads the variable itself (connect3) over the dimensions that variable declares. A file whose
// connect3 declared other, longer dimensions made ex_get_conn write past getme's buffer: a heap
// overflow inside netCDF (ncx_getn_int_longlong), found by the exodus fuzz target on 2026-11-27
// and located with valgrind, since ASan does not see writes by uninstrumented libraries. So every
// variable the reader has the library read must have exactly the dimensions Exodus II defines for
// it (exodusII_int.h); "#" stands for the block or set number ending the variable's name, "*"
// for any dimension (the name length of a names variable: the library reads at most the API's
// name length of it).
struct VariableShape {
  const char* name;  // without the trailing number, if `numbered`
  bool numbered;
  std::vector<const char*> dimensions;
};

const std::vector<VariableShape>& ExodusVariableShapes() {
  static const std::vector<VariableShape> shapes = {
      {"coord", false, {"num_dim", "num_nodes"}},
      {"coordx", false, {"num_nodes"}},
      {"coordy", false, {"num_nodes"}},
      {"coordz", false, {"num_nodes"}},
      {"coor_names", false, {"num_dim", "*"}},
      {"node_num_map", false, {"num_nodes"}},
      {"elem_num_map", false, {"num_elem"}},
      {"eb_status", false, {"num_el_blk"}},
      {"eb_prop", true, {"num_el_blk"}},
      {"eb_names", false, {"num_el_blk", "*"}},
      {"connect", true, {"num_el_in_blk#", "num_nod_per_el#"}},
      {"attrib", true, {"num_el_in_blk#", "num_att_in_blk#"}},
      {"attrib_name", true, {"num_att_in_blk#", "*"}},
      {"ss_status", false, {"num_side_sets"}},
      {"ss_prop", true, {"num_side_sets"}},
      {"ss_names", false, {"num_side_sets", "*"}},
      {"elem_ss", true, {"num_side_ss#"}},
      {"side_ss", true, {"num_side_ss#"}},
      {"dist_fact_ss", true, {"num_df_ss#"}},
      {"ns_status", false, {"num_node_sets"}},
      {"ns_prop", true, {"num_node_sets"}},
      {"ns_names", false, {"num_node_sets", "*"}},
      {"node_ns", true, {"num_nod_ns#"}},
      {"dist_fact_ns", true, {"num_nod_ns#"}},
  };
  return shapes;
}

// The shape Exodus II defines for a variable named `name`, and the number ending it; nullptr for
// variables the reader never has the library read.
const VariableShape* ShapeOf(absl::string_view name, absl::string_view* number) {
  std::size_t digits = name.size();
  while (digits > 0 && absl::ascii_isdigit(static_cast<unsigned char>(name[digits - 1]))) --digits;
  const bool numbered = digits < name.size();
  for (const VariableShape& shape : ExodusVariableShapes()) {
    if (shape.numbered == numbered && name.substr(0, digits) == shape.name) {
      *number = name.substr(digits);
      return &shape;
    }
  }
  return nullptr;
}

absl::Status CheckShape(int ncid, int variable, absl::string_view name) {
  absl::string_view number;
  const VariableShape* shape = ShapeOf(name, &number);
  if (shape == nullptr) return absl::OkStatus();
  std::vector<std::string> expected;
  for (const char* dimension : shape->dimensions) {
    expected.push_back(absl::StrReplaceAll(dimension, {{"#", number}}));
  }
  int rank = 0;
  std::vector<std::string> found;
  if (Exodus().nc_inq_varndims(ncid, variable, &rank) == NC_NOERR && rank >= 0 &&
      rank <= NC_MAX_VAR_DIMS) {
    std::vector<int> ids(static_cast<std::size_t>(rank));
    if (Exodus().nc_inq_vardimid(ncid, variable, ids.data()) == NC_NOERR) {
      for (const int id : ids) {
        char dimension[NC_MAX_NAME + 1] = {};
        if (Exodus().nc_inq_dimname(ncid, id, dimension) != NC_NOERR) break;
        found.emplace_back(dimension);
      }
    }
  }
  bool same = found.size() == expected.size();
  for (std::size_t k = 0; same && k < found.size(); ++k) {
    same = expected[k] == "*" || found[k] == expected[k];
  }
  if (!same) {
    return absl::InvalidArgumentError(
        absl::StrCat("variable '", name, "' has dimensions (", absl::StrJoin(found, ", "),
                     "); Exodus II defines it over (", absl::StrJoin(expected, ", "), ")"));
  }
  return absl::OkStatus();
}

// InvalidArgument for a netCDF file whose attributes or variables the Exodus library cannot read
// safely; OK when it is fine or not netCDF at all (ex_open then says why it cannot open it).
absl::Status CheckNetcdfHeader(const std::string& path) {
  int ncid = -1;
  if (Exodus().nc_open(path.c_str(), NC_NOWRITE, &ncid) != NC_NOERR) return absl::OkStatus();
  absl::Status status = CheckAttributes(ncid, NC_GLOBAL, "global");
  int variables = 0;
  if (status.ok() && Exodus().nc_inq_nvars(ncid, &variables) == NC_NOERR) {
    for (int variable = 0; variable < variables && status.ok(); ++variable) {
      char name[NC_MAX_NAME + 1] = {};
      if (Exodus().nc_inq_varname(ncid, variable, name) != NC_NOERR) continue;
      status = CheckAttributes(ncid, variable, absl::StrCat("variable '", name, "'"));
      if (status.ok()) status = CheckShape(ncid, variable, name);
    }
  }
  Exodus().nc_close(ncid);
  return status;
}

}  // namespace

std::unique_lock<std::mutex> LockExodusLibrary() {
  static std::mutex mutex;
  return std::unique_lock<std::mutex>(mutex);
}

absl::Status ExodusError(absl::string_view context) {
  const char* message = nullptr;
  const char* function = nullptr;
  int code = 0;
  Exodus().ex_get_err(&message, &function, &code);
  std::string text = absl::StrCat(context, ": ");
  if (message != nullptr && *message != '\0') {
    absl::StrAppend(&text, message);
  } else {
    absl::StrAppend(&text, "the Exodus library reports an error");
  }
  if (code != 0 && !IsExodusOwnCode(code))
    absl::StrAppend(&text, " (", Exodus().nc_strerror(code), ")");
  return absl::InvalidArgumentError(text);
}

absl::StatusOr<ExodusFile> ExodusFile::Open(const std::string& path) {
  if (absl::Status status = LoadExodusFunctions(); !status.ok()) return status;
  std::error_code error;
  if (!std::filesystem::exists(path, error)) {
    return absl::NotFoundError(absl::StrCat("cannot open '", path, "': No such file or directory"));
  }
  if (std::filesystem::is_directory(path, error)) {
    return absl::InvalidArgumentError(absl::StrCat("cannot open '", path, "': is a directory"));
  }
  if (absl::Status status = CheckNetcdfClassicHeader(path); !status.ok()) return status;
  if (absl::Status status = CheckNetcdfHeader(path); !status.ok()) return status;
  int cpu_word_size = 8;  // the API hands out doubles, whatever the file stores
  int io_word_size = 0;
  float version = 0;
  const int id = Exodus().ex_open(path.c_str(), EX_READ, &cpu_word_size, &io_word_size, &version);
  if (id < 0) return ExodusError("not an Exodus II file");
  ExodusFile file(id);
  if (Exodus().ex_set_int64_status(id, EX_ALL_INT64_API) < 0) {
    return ExodusError("cannot switch the Exodus API to 64-bit integers");
  }
  return file;
}

absl::StatusOr<ExodusFile> ExodusFile::Create(const std::string& path, bool int64_db) {
  if (absl::Status status = LoadExodusFunctions(); !status.ok()) return status;
  int cpu_word_size = 8;
  int io_word_size = 8;
  int mode = EX_CLOBBER | EX_LARGE_MODEL;
  if (int64_db) mode |= EX_ALL_INT64_DB | EX_NETCDF4;  // netCDF-3 has no 64-bit integers
  const int id = Exodus().ex_create(path.c_str(), mode, &cpu_word_size, &io_word_size);
  if (id < 0) return ExodusError(absl::StrCat("cannot create '", path, "'"));
  ExodusFile file(id);
  if (Exodus().ex_set_int64_status(id, EX_ALL_INT64_API) < 0) {
    return ExodusError("cannot switch the Exodus API to 64-bit integers");
  }
  return file;
}

absl::Status ExodusFile::Close() {
  if (id_ < 0) return absl::OkStatus();
  const int id = id_;
  id_ = -1;
  if (Exodus().ex_close(id) < 0) return ExodusError("cannot close the Exodus file");
  return absl::OkStatus();
}

ExodusFile::~ExodusFile() {
  if (id_ >= 0) Exodus().ex_close(id_);
}

absl::StatusOr<TemporaryFile> TemporaryFile::Create(absl::string_view suffix) {
  std::error_code error;
  std::filesystem::path directory = std::filesystem::temp_directory_path(error);
  if (error) directory = "/tmp";
  std::string pattern = (directory / "getme-exodus-XXXXXX").string();
  pattern.append(suffix.data(), suffix.size());
  std::vector<char> name(pattern.begin(), pattern.end());
  name.push_back('\0');
  const int fd = mkstemps(name.data(), static_cast<int>(suffix.size()));
  if (fd < 0) {
    return absl::ErrnoToStatus(
        errno, absl::StrCat("cannot create a temporary file in ", directory.string()));
  }
  close(fd);
  return TemporaryFile(std::string(name.data()));
}

TemporaryFile::~TemporaryFile() {
  if (!path_.empty()) std::remove(path_.c_str());
}

}  // namespace getme::formats
