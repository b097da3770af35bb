#pragma once

#include <string>

#include "absl/status/status.h"
#include "absl/status/statusor.h"
#include "absl/strings/string_view.h"

namespace getme::formats {

// The whole file. NotFound / PermissionDenied / … name the path; a directory is InvalidArgument.
absl::StatusOr<std::string> ReadFileBytes(const std::string& path);

// Writes `bytes` to a temporary file beside `path` and renames it over `path` once complete, so
// a failed or interrupted write never leaves a truncated file under the final name.
absl::Status WriteFileAtomically(const std::string& path, absl::string_view bytes);

}  // namespace getme::formats
