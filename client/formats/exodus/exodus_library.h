#pragma once

#include <mutex>
#include <string>

#include "absl/status/status.h"
#include "absl/status/statusor.h"
#include "absl/strings/string_view.h"

namespace getme::formats {

// The boundary to Debian's Exodus II C library (libexodusii-dev, API 6.02, over netCDF).
//
// The library keeps process-wide state: its error value and last message (exerrval, ex_err),
// its options (ex_opts) and netCDF's table of open files. It is not thread-safe, so every call
// into it runs under this one lock; a client that reads two Exodus files from two threads
// serialises them instead of corrupting each other's error messages.
std::unique_lock<std::mutex> LockExodusLibrary();

// InvalidArgument "`context`: <the library's last message> (<netCDF's text for its code>)".
// Call right after a failing ex_* function, under the lock.
absl::Status ExodusError(absl::string_view context);

// An open Exodus file, closed on destruction. Open and create under the lock; both load the
// library first (exodus_functions.h), FailedPrecondition when it is not installed.
class ExodusFile {
 public:
  // Opens for reading; NotFound for a missing path, InvalidArgument when the library refuses
  // the file (not netCDF, not Exodus).
  static absl::StatusOr<ExodusFile> Open(const std::string& path);
  // Creates (clobbering) a netCDF 64-bit-offset Exodus file storing doubles; `int64_db` makes
  // it store ids and indices as 64-bit integers (more than 2^31 - 1 nodes or elements).
  static absl::StatusOr<ExodusFile> Create(const std::string& path, bool int64_db);

  ExodusFile(ExodusFile&& other) noexcept : id_(other.id_) { other.id_ = -1; }
  ExodusFile& operator=(ExodusFile&&) = delete;
  ExodusFile(const ExodusFile&) = delete;
  ~ExodusFile();

  int id() const { return id_; }
  // Closes now, reporting the library's error (a write may fail only when buffers are flushed).
  absl::Status Close();

 private:
  explicit ExodusFile(int id) : id_(id) {}
  int id_ = -1;
};

// A temporary file path that is removed on destruction. The Exodus library reads and writes
// only named files (ex_open / ex_create take a path; netCDF's in-memory open is not reachable
// through it), so bytes are passed through one of these.
class TemporaryFile {
 public:
  static absl::StatusOr<TemporaryFile> Create(absl::string_view suffix);
  TemporaryFile(TemporaryFile&& other) noexcept : path_(std::move(other.path_)) {
    other.path_.clear();
  }
  TemporaryFile& operator=(TemporaryFile&&) = delete;
  TemporaryFile(const TemporaryFile&) = delete;
  ~TemporaryFile();

  const std::string& path() const { return path_; }

 private:
  explicit TemporaryFile(std::string path) : path_(std::move(path)) {}
  std::string path_;
};

}  // namespace getme::formats
