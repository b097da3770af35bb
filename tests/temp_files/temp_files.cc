#include "temp_files.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <iostream>
#include <mutex>
#include <set>

namespace getme::testing {
namespace {

class TempFileCleaner : public ::testing::EmptyTestEventListener {
 public:
  void Add(const std::string& path) {
    const std::lock_guard<std::mutex> lock(mutex_);
    paths_.insert(path);
  }

  void OnTestProgramEnd(const ::testing::UnitTest& unit_test) override {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (paths_.empty()) return;
    if (!unit_test.Passed()) {
      std::cerr << "The failed run's " << paths_.size() << " temporary files are kept, e.g. "
                << *paths_.begin() << "\n";
      return;
    }
    for (const std::string& path : paths_) {
      std::error_code ignored;  // a path the test never wrote, or removed itself
      std::filesystem::remove_all(path, ignored);
    }
  }

 private:
  std::mutex mutex_;
  std::set<std::string> paths_;
};

// Appended to GoogleTest's listeners, which own it, on first use (inside a test, while no event
// is being sent).
TempFileCleaner& Cleaner() {
  static TempFileCleaner* const cleaner = [] {
    auto* listener = new TempFileCleaner;
    ::testing::UnitTest::GetInstance()->listeners().Append(listener);
    return listener;
  }();
  return *cleaner;
}

}  // namespace

std::string DeleteWhenTheRunPasses(std::string path) {
  Cleaner().Add(path);
  return path;
}

}  // namespace getme::testing
