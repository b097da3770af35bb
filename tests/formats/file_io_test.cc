// ReadFileBytes gives a file's bytes exactly, whatever its size and whether or not it has one
// (a FIFO), and names the path when it cannot.

#include "formats/file_io.h"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <thread>

#include "absl/strings/str_cat.h"

namespace getme::formats {
namespace {

std::string TemporaryPath(const std::string& name) {
  return (std::filesystem::path(::testing::TempDir()) /
          absl::StrCat("file_io_test_", ::getpid(), "_", name))
      .string();
}

std::string RandomBytes(std::size_t size, unsigned seed) {
  std::mt19937 random(seed);
  std::string bytes(size, '\0');
  for (char& byte : bytes) byte = static_cast<char>(random() & 0xff);
  return bytes;
}

TEST(ReadFileBytes, RegularFilesOfEverySizeAroundTheReadChunkComeBackExactly) {
  for (const std::size_t size : {0, 1, 4095, 65535, 65536, 65537, 200003}) {
    SCOPED_TRACE(absl::StrCat(size, " bytes"));
    const std::string path = TemporaryPath(absl::StrCat("regular_", size));
    const std::string bytes = RandomBytes(size, static_cast<unsigned>(size));
    ASSERT_TRUE(WriteFileAtomically(path, bytes).ok());
    const absl::StatusOr<std::string> read = ReadFileBytes(path);
    ASSERT_TRUE(read.ok()) << read.status();
    EXPECT_EQ(read->size(), size);
    EXPECT_TRUE(*read == bytes);
    std::filesystem::remove(path);
  }
}

// A FIFO has no size up front: everything written into it is read, in chunks, to its end.
TEST(ReadFileBytes, AFifoIsReadToItsEnd) {
  const std::string path = TemporaryPath("fifo");
  ASSERT_EQ(::mkfifo(path.c_str(), 0600), 0);
  const std::string bytes = RandomBytes(150001, 7);
  std::thread writer([&] {
    std::ofstream stream(path, std::ios::binary);
    stream.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  });
  const absl::StatusOr<std::string> read = ReadFileBytes(path);
  writer.join();
  std::filesystem::remove(path);
  ASSERT_TRUE(read.ok()) << read.status();
  EXPECT_EQ(read->size(), bytes.size());
  EXPECT_TRUE(*read == bytes);
}

TEST(ReadFileBytes, AMissingFileOrADirectoryIsNamed) {
  const std::string missing = TemporaryPath("missing.vtk");
  const absl::StatusOr<std::string> absent = ReadFileBytes(missing);
  EXPECT_EQ(absent.status().code(), absl::StatusCode::kNotFound);
  EXPECT_EQ(absent.status().message(),
            absl::StrCat("cannot open '", missing, "': No such file or directory"));

  const std::string directory = ::testing::TempDir();
  const absl::StatusOr<std::string> folder = ReadFileBytes(directory);
  EXPECT_EQ(folder.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_EQ(folder.status().message(),
            absl::StrCat("'", directory, "' is a directory, not a mesh file"));
}

}  // namespace
}  // namespace getme::formats
