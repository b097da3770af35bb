#include "events/trace_file.h"

#include <cerrno>

#include "absl/strings/str_cat.h"

namespace getme::events {

absl::StatusOr<std::unique_ptr<TraceFile>> TraceFile::Open(const std::string& path) {
  std::FILE* file = std::fopen(path.c_str(), "w");
  if (file == nullptr) {
    const int error = errno;
    return absl::ErrnoToStatus(error, absl::StrCat("cannot write the trace '", path, "'"));
  }
  return std::unique_ptr<TraceFile>(new TraceFile(path, file));
}

TraceFile::~TraceFile() {
  if (file_ != nullptr) std::fclose(file_);
}

void TraceFile::WriteLine(const std::string& json) {
  if (file_ == nullptr) return;
  std::fputs(json.c_str(), file_);
  std::fputc('\n', file_);
}

absl::Status TraceFile::Close() {
  if (file_ == nullptr) return absl::OkStatus();
  const bool failed = std::ferror(file_) != 0;
  const bool close_failed = std::fclose(file_) != 0;
  file_ = nullptr;
  if (failed || close_failed) {
    return absl::DataLossError(absl::StrCat("writing the trace '", path_, "' failed"));
  }
  return absl::OkStatus();
}

}  // namespace getme::events
