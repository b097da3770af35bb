#include "formats/cgns/cgns_library.h"

#include <cgnslib.h>
#include <stdlib.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <system_error>
#include <utility>

#include "absl/strings/match.h"
#include "absl/strings/str_cat.h"
#include "formats/cgns/cgns_functions.h"

namespace getme::formats::cgns {

std::mutex& LibraryMutex() {
  static std::mutex mutex;
  return mutex;
}

absl::Status LibraryError(absl::StatusCode status_code, absl::string_view what) {
  return absl::Status(status_code, absl::StrCat(what, ": ", Cgns().cg_get_error()));
}

namespace {

// The CGNS library 3.4 hands every file that HDF5 does not open to its ADF core, which asserts
// (aborting the process) on some headers it cannot parse: ADFI_read_file_header's
// `assert(ADF_file[file_index].format != UNDEFINED_FORMAT)` fires on a 23-byte file starting
// "\x89H" (found by fuzz/cgns_fuzzer.cc). So only files that open with the HDF5 signature
// (HDF5 File Format Specification, "Format Signature"; CGNS writes no user block, so it is at
// offset 0) or a complete ADF file header reach cg_open. The ADF header (ADF_internals.c,
// ADFI_read_file_header) is "ADF Database Version" at byte 4, the tags AdF0..AdF5 at 32, 64,
// 96, 102, 130 and 182, the numeric format (B, L, C or N) at 100 and the OS size (L or B) at 101.
absl::Status CheckSignature(const std::string& path) {
  char head[186] = {};
  std::FILE* file = std::fopen(path.c_str(), "rb");
  if (file == nullptr) {
    return absl::NotFoundError(absl::StrCat("cannot open '", path, "': ", std::strerror(errno)));
  }
  const std::size_t size = std::fread(head, 1, sizeof(head), file);
  std::fclose(file);
  const absl::string_view bytes(head, size);
  if (absl::StartsWith(bytes, absl::string_view("\x89HDF\r\n\x1a\n", 8))) {
    return absl::OkStatus();
  }
  if (bytes.size() >= 24 && bytes.substr(4, 20) == "ADF Database Version") {
    constexpr std::pair<int, const char*> kTags[] = {{32, "AdF0"},  {64, "AdF1"},  {96, "AdF2"},
                                                     {102, "AdF3"}, {130, "AdF4"}, {182, "AdF5"}};
    bool complete = bytes.size() == sizeof(head);
    for (const auto& [offset, tag] : kTags) {
      complete = complete && bytes.substr(offset, 4) == tag;
    }
    complete = complete && absl::string_view("BLCN").find(bytes[100]) != absl::string_view::npos &&
               absl::string_view("LB").find(bytes[101]) != absl::string_view::npos;
    if (complete) return absl::OkStatus();
    return absl::InvalidArgumentError(
        "not a CGNS file: its ADF file header is truncated or damaged (a tag AdF0..AdF5, the "
        "numeric format or the OS size is missing)");
  }
  return absl::InvalidArgumentError(
      "not a CGNS file: it opens with neither the HDF5 signature nor an ADF file header");
}

}  // namespace

absl::StatusOr<OpenFile> OpenFile::Open(const std::string& path, int mode) {
  if (absl::Status status = LoadCgnsFunctions(); !status.ok()) return status;
  if (mode == CG_MODE_READ) {
    struct stat info {};
    if (stat(path.c_str(), &info) != 0) {
      return absl::NotFoundError(absl::StrCat("cannot open '", path, "': ", std::strerror(errno)));
    }
    if (S_ISDIR(info.st_mode)) {
      return absl::InvalidArgumentError(absl::StrCat("'", path, "' is a directory"));
    }
    if (absl::Status status = CheckSignature(path); !status.ok()) return status;
  } else if (Cgns().cg_set_file_type(CG_FILE_HDF5) != CG_OK) {
    // The file type is a library global: set it for every write, whatever an earlier call set.
    return LibraryError(absl::StatusCode::kInternal, "cg_set_file_type(HDF5)");
  }
  int handle = -1;
  if (Cgns().cg_open(path.c_str(), mode, &handle) != CG_OK) {
    return LibraryError(
        mode == CG_MODE_READ ? absl::StatusCode::kInvalidArgument : absl::StatusCode::kInternal,
        mode == CG_MODE_READ ? "not a file the CGNS library opens (cg_open)"
                             : "cannot create the CGNS file (cg_open)");
  }
  return OpenFile(handle);
}

absl::Status OpenFile::Close() {
  const int handle = handle_;
  handle_ = -1;
  if (handle >= 0 && Cgns().cg_close(handle) != CG_OK) {
    return LibraryError(absl::StatusCode::kInternal, "cg_close");
  }
  return absl::OkStatus();
}

OpenFile::~OpenFile() {
  // Only on a path that already failed: its error is the one reported, not cg_close's.
  if (handle_ >= 0) Cgns().cg_close(handle_);
}

absl::StatusOr<TemporaryFile> TemporaryFile::Create() {
  std::error_code error;
  std::string base = std::filesystem::temp_directory_path(error).string();
  if (error) base = "/tmp";
  std::string pattern = absl::StrCat(base, "/.getme-cgns-XXXXXX");
  const int descriptor = mkstemp(pattern.data());
  if (descriptor < 0) {
    return absl::UnavailableError(
        absl::StrCat("cannot create a temporary file in '", base, "': ", std::strerror(errno)));
  }
  close(descriptor);
  return TemporaryFile(std::move(pattern));
}

TemporaryFile::~TemporaryFile() {
  if (!path_.empty()) unlink(path_.c_str());
}

}  // namespace getme::formats::cgns
