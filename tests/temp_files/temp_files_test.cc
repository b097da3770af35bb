// DeleteWhenTheRunPasses leaves a file alone while the run goes on; that it is gone once this
// passing run has ended is checked after it by the ctest test
// temp_files_are_gone_after_a_passing_run (tests/temp_files/CMakeLists.txt).

#include "temp_files.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace getme::testing {
namespace {

TEST(DeleteWhenTheRunPasses, ReturnsThePathAndKeepsTheFileUntilTheRunEnds) {
  const std::string path = GETME_TEMP_FILES_PROBE;
  std::filesystem::remove_all(path);
  EXPECT_EQ(DeleteWhenTheRunPasses(path), path);
  std::filesystem::create_directories(path);
  std::ofstream(path + "/inside.txt") << "probe\n";
  EXPECT_EQ(DeleteWhenTheRunPasses(path), path);  // naming a path twice is allowed
  EXPECT_TRUE(std::filesystem::exists(path + "/inside.txt"));
}

}  // namespace
}  // namespace getme::testing
