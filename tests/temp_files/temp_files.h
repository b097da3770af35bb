#pragma once

#include <string>

namespace getme::testing {

// Deletes `path` (a file, or a directory with what it holds) when the test executable ends with
// every test passed, and returns it. After a failure the files stay for a look, and the end of
// the run says where. Without this every run of the suite left about a hundred files in the
// temp directory. Safe to call from any thread, any number of times for one path.
std::string DeleteWhenTheRunPasses(std::string path);

}  // namespace getme::testing
