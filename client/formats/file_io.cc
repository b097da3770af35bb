#include "formats/file_io.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "absl/cleanup/cleanup.h"
#include "absl/strings/str_cat.h"

namespace getme::formats {

absl::StatusOr<std::string> ReadFileBytes(const std::string& path) {
  std::error_code error_code;
  if (std::filesystem::is_directory(path, error_code)) {
    return absl::InvalidArgumentError(absl::StrCat("'", path, "' is a directory, not a mesh file"));
  }
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) {
    const int error = errno;
    return absl::ErrnoToStatus(error, absl::StrCat("cannot open '", path, "'"));
  }
  const absl::Cleanup close_file = [fd] { ::close(fd); };
  // One buffer of the file's size, filled by read(2): streaming it through an ostringstream grew
  // and copied the buffer again and again, and was 15 % of `getme convert` on a 3.7 MB file.
  // A pipe or a file that grows while being read has no (right) size up front: what follows the
  // stated size is read in chunks until end of file.
  struct stat info {};
  std::string bytes;
  if (::fstat(fd, &info) == 0 && S_ISREG(info.st_mode) && info.st_size > 0) {
    // One byte more than the file, so the read that finds its end needs no larger buffer.
    bytes.resize(static_cast<std::size_t>(info.st_size) + 1);
  }
  constexpr std::size_t kChunk = std::size_t{1} << 16;
  std::size_t filled = 0;
  while (true) {
    if (filled == bytes.size()) bytes.resize(bytes.size() + kChunk);
    const ssize_t got = ::read(fd, bytes.data() + filled, bytes.size() - filled);
    if (got < 0) {
      if (errno == EINTR) continue;
      const int error = errno;
      return absl::ErrnoToStatus(error, absl::StrCat("cannot read '", path, "'"));
    }
    if (got == 0) break;
    filled += static_cast<std::size_t>(got);
  }
  bytes.resize(filled);
  return bytes;
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
