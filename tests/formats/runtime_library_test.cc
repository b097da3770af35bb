// Format libraries loaded when first needed (formats/runtime_library.h): what a user sees when
// one is missing, and that the CLI does not load them before a file needs them.
#include "formats/runtime_library.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "absl/strings/match.h"

namespace getme::formats {
namespace {

TEST(RuntimeLibraryTest, AMissingLibraryNamesItsFormatAndPackage) {
  const absl::StatusOr<RuntimeLibrary> library =
      RuntimeLibrary::Open("libgetme-no-such-library.so.7", "Imaginary", "libimaginary7");
  ASSERT_FALSE(library.ok());
  EXPECT_EQ(library.status().code(), absl::StatusCode::kFailedPrecondition);
  EXPECT_TRUE(absl::StartsWith(library.status().message(),
                               "Imaginary files need libgetme-no-such-library.so.7 (Debian "
                               "package libimaginary7), which cannot be loaded: "))
      << library.status();
}

TEST(RuntimeLibraryTest, BindsAFunctionAndNamesAMissingOne) {
  const absl::StatusOr<RuntimeLibrary> libm = RuntimeLibrary::Open("libm.so.6", "Test", "libc6");
  ASSERT_TRUE(libm.ok()) << libm.status();
  double (*fabs_function)(double) = nullptr;
  ASSERT_TRUE(libm->Bind("fabs", fabs_function).ok());
  EXPECT_EQ(fabs_function(-2.5), 2.5);
  void (*missing)() = nullptr;
  const absl::Status status = libm->Bind("getme_no_such_function", missing);
  EXPECT_EQ(status.code(), absl::StatusCode::kInternal);
  EXPECT_TRUE(
      absl::StartsWith(status.message(), "libm.so.6 has no function getme_no_such_function"))
      << status;
  EXPECT_EQ(missing, nullptr);
}

std::string ReadOwnMaps() {
  std::ifstream maps("/proc/self/maps");
  std::stringstream text;
  text << maps.rdbuf();
  return text.str();
}

// The process's mappings as it started: read during static initialisation, before main and so
// before any test of this binary could read a CGNS or Exodus file (the format tests do, and a
// whole-binary run would otherwise find the libraries they loaded).
const std::string kMapsAtStart = ReadOwnMaps();

// What the lazy loading is for: a process that reads no CGNS or Exodus file never maps their
// libraries (nor HDF5, netCDF and MPI behind them). This binary links every format library the
// CLI links, so a format library linked again would be mapped at its start.
TEST(RuntimeLibraryTest, NoFormatLibraryIsLoadedBeforeAFileNeedsIt) {
  ASSERT_TRUE(absl::StrContains(kMapsAtStart, "libstdc++")) << "no mappings were read";
  for (const char* library : {"libcgns", "libexoIIv2c", "libnetcdf", "libhdf5", "libmpi"}) {
    EXPECT_FALSE(absl::StrContains(kMapsAtStart, library)) << library << " is mapped";
  }
}

}  // namespace
}  // namespace getme::formats
