#pragma once

#include <mutex>
#include <string>

#include "absl/status/status.h"
#include "absl/status/statusor.h"
#include "absl/strings/string_view.h"

namespace getme::formats::cgns {

// The CGNS mid-level library keeps its open files, its "current node" (cg_goto) and its last
// error in process-wide globals and is not thread-safe: every use holds this lock for the whole
// file, from cg_open to cg_close.
std::mutex& LibraryMutex();

// `status_code` with "<what>: <cg_get_error() text>", for a failed cg_* call.
absl::Status LibraryError(absl::StatusCode status_code, absl::string_view what);

// An open CGNS file, closed (cg_close) when it goes out of scope.
class OpenFile {
 public:
  // mode: CG_MODE_READ or CG_MODE_WRITE. Loads the library first (cgns_functions.h):
  // FailedPrecondition when it is not installed. InvalidArgument with the library's text when the
  // file is not one the library can open (cg_open), NotFound when it does not exist (read).
  static absl::StatusOr<OpenFile> Open(const std::string& path, int mode);
  OpenFile(OpenFile&& other) noexcept : handle_(other.handle_) { other.handle_ = -1; }
  OpenFile& operator=(OpenFile&&) = delete;
  ~OpenFile();

  int handle() const { return handle_; }
  // Closes now (a write's data reaches the file only here): the library's error if it fails.
  absl::Status Close();

 private:
  explicit OpenFile(int handle) : handle_(handle) {}
  int handle_ = -1;
};

// A file in the temporary directory, removed when this goes out of scope. The CGNS library
// reads and writes paths only (HDF5 and ADF both open files by name), so bytes in memory pass
// through one of these.
class TemporaryFile {
 public:
  // In the system's temporary directory (TMPDIR).
  static absl::StatusOr<TemporaryFile> Create();
  TemporaryFile(TemporaryFile&& other) noexcept : path_(std::move(other.path_)) {
    other.path_.clear();
  }
  TemporaryFile& operator=(TemporaryFile&&) = delete;
  ~TemporaryFile();

  const std::string& path() const { return path_; }

 private:
  explicit TemporaryFile(std::string path) : path_(std::move(path)) {}
  std::string path_;
};

}  // namespace getme::formats::cgns
