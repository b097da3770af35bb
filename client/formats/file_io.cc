#include "formats/file_io.h"

#include <cerrno>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "absl/strings/str_cat.h"

namespace getme::formats {

absl::StatusOr<std::string> ReadFileBytes(const std::string& path) {
  std::error_code error_code;
  if (std::filesystem::is_directory(path, error_code)) {
    return absl::InvalidArgumentError(absl::StrCat("'", path, "' is a directory, not a mesh file"));
  }
  std::ifstream stream(path, std::ios::binary);
  if (!stream) {
    const int error = errno;
    return absl::ErrnoToStatus(error, absl::StrCat("cannot open '", path, "'"));
  }
  std::ostringstream contents;
  contents << stream.rdbuf();
  if (stream.bad()) {
    const int error = errno;
    return absl::ErrnoToStatus(error, absl::StrCat("cannot read '", path, "'"));
  }
  return std::move(contents).str();
}

absl::Status WriteFileAtomically(const std::string& path, absl::string_view bytes) {
  const std::string temporary = path + ".tmp";
  {
    std::ofstream stream(temporary, std::ios::binary | std::ios::trunc);
    if (!stream) {
      const int error = errno;
      return absl::ErrnoToStatus(error, absl::StrCat("cannot write '", path, "'"));
    }
    stream.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    stream.close();
    if (!stream) {
      const int error = errno;
      std::remove(temporary.c_str());
      return absl::ErrnoToStatus(error, absl::StrCat("cannot write '", path, "'"));
    }
  }
  if (std::rename(temporary.c_str(), path.c_str()) != 0) {
    const int error = errno;
    std::remove(temporary.c_str());
    return absl::ErrnoToStatus(error, absl::StrCat("cannot write '", path, "'"));
  }
  return absl::OkStatus();
}

}  // namespace getme::formats
