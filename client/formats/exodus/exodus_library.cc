#include "formats/exodus/exodus_library.h"

#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <system_error>
#include <vector>

#include "absl/strings/str_cat.h"
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

// InvalidArgument for a netCDF file whose attributes the Exodus library cannot read safely; OK
// when it is fine or not netCDF at all (ex_open then says why it cannot open it).
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
