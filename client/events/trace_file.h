#pragma once

#include <cstdio>
#include <memory>
#include <string>

#include "absl/status/statusor.h"
#include "getme/smoothing/progress.h"

namespace getme::events {

// `getme smooth --trace FILE`: the run's progress events, then its result, one JSON object per
// line, exactly as --json prints them to stdout; `getme report --trace` draws them.
class TraceFile {
 public:
  static absl::StatusOr<std::unique_ptr<TraceFile>> Open(const std::string& path);
  ~TraceFile();
  TraceFile(const TraceFile&) = delete;
  TraceFile& operator=(const TraceFile&) = delete;

  void WriteLine(const std::string& json);
  // Flushes and reports a write error (a full disk) once, at the end.
  absl::Status Close();

 private:
  TraceFile(std::string path, std::FILE* file) : path_(std::move(path)), file_(file) {}
  std::string path_;
  std::FILE* file_;
};

}  // namespace getme::events
