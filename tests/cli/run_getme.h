#pragma once

#include <string>
#include <vector>

namespace getme::cli::testing {

struct RunResult {
  int exit_status = -1;  // -1 if the process did not exit normally
  std::string out;       // stdout
  std::string err;       // stderr
};

// Runs the built `getme` executable (GETME_BINARY_DIR/bin/getme) with `args`, stdout and stderr
// captured through files (so stderr is not a terminal).
RunResult RunGetme(const std::vector<std::string>& args);
// The same for any executable (e.g. GETME_BINARY_DIR/bin/getme-meshgen to make an input).
RunResult RunProgram(const std::string& binary, const std::vector<std::string>& args);

// A path in the test temp directory, unique to the running test. What is there is deleted when the
// test executable ends with every test passed.
std::string TempPath(const std::string& name);

std::vector<std::string> Lines(const std::string& text);

}  // namespace getme::cli::testing
