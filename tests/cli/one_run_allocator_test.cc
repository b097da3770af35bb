#include "cli/one_run_allocator.h"

#include <gtest/gtest.h>
#include <sys/mman.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "getme_support/sanitizer_allocator.h"

namespace getme::cli {
namespace {

// Whether the mapping that holds `address` carries the huge-page advice: "hg" among the VmFlags
// of its entry in /proc/self/smaps.
bool AdvisedForHugePages(const void* address) {
  const auto at = reinterpret_cast<std::uintptr_t>(address);
  std::ifstream smaps("/proc/self/smaps");
  std::string line;
  bool inside = false;
  while (std::getline(smaps, line)) {
    unsigned long begin = 0, end = 0;
    if (std::sscanf(line.c_str(), "%lx-%lx ", &begin, &end) == 2 &&
        line.find('-') < line.find(' ')) {
      inside = begin <= at && at < end;
    } else if (inside && line.rfind("VmFlags:", 0) == 0) {
      std::istringstream flags(line.substr(8));
      std::string flag;
      while (flags >> flag) {
        if (flag == "hg") return true;
      }
      return false;
    }
  }
  return false;
}

// A child's exit code when this kernel (or its /proc) does not show the advice on a mapping of
// the test's own: then nothing here can be checked.
constexpr int kKernelShowsNoAdvice = 77;

// ... and when glibc advises its blocks already (GLIBC_TUNABLES=glibc.malloc.hugetlb=1).
constexpr int kAdvisedBefore = 78;

bool KernelShowsTheAdvice() {
  constexpr std::size_t kSize = std::size_t{4} << 20;
  void* mapping = mmap(nullptr, kSize, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (mapping == MAP_FAILED) return false;
  const bool shown = madvise(mapping, kSize, MADV_HUGEPAGE) == 0 && AdvisedForHugePages(mapping);
  munmap(mapping, kSize);
  return shown;
}

// What a child process finds, as its exit code: 0 when everything holds.
int CheckInAFreshProcess() {
  if (!KernelShowsTheAdvice()) return kKernelShowsNoAdvice;
  // Before: a 4 MiB block is on memory without the advice.
  char* before = static_cast<char*>(std::malloc(4 << 20));
  if (before == nullptr) return 10;
  if (AdvisedForHugePages(before)) return kAdvisedBefore;
  std::free(before);
  PrepareAllocatorForOneRun();
  char* block = static_cast<char*>(std::malloc(4 << 20));
  if (block == nullptr) return 11;
  std::memset(block, 1, 4 << 20);
  if (!AdvisedForHugePages(block)) return 12;
  // The pages given back read as zeros again: calloc, which counts on fresh heap being zero,
  // still returns zeros, and the allocator's own records stay whole through many blocks.
  for (int round = 0; round < 200; ++round) {
    const std::size_t size = (static_cast<std::size_t>(round) * 7919 % 3000) * 1024 + 16;
    auto* zeros = static_cast<unsigned char*>(std::calloc(size, 1));
    if (zeros == nullptr) return 13;
    for (std::size_t i = 0; i < size; i += 512) {
      if (zeros[i] != 0) return 14;
    }
    std::memset(zeros, 0xab, size);
    if (round % 3 != 0) std::free(zeros);
  }
  std::free(block);
  return 0;
}

// Runs `check` in a forked child, whose allocator no test has set up yet, and returns its exit
// code; −1 if the child could not start or did not exit.
int ExitCodeInAFreshProcess(int (*check)()) {
  const pid_t child = fork();
  if (child < 0) return -1;
  if (child == 0) _exit(check());
  int status = 0;
  if (waitpid(child, &status, 0) != child || !WIFEXITED(status)) return -1;
  return WEXITSTATUS(status);
}

TEST(OneRunAllocatorTest, HeapBlocksLandOnHugePageAdvisedMemoryAndCallocStillZeroes) {
  if (kSanitizerAllocator) GTEST_SKIP() << "the sanitizers replace malloc";
  if (!std::filesystem::exists("/sys/kernel/mm/transparent_hugepage")) {
    GTEST_SKIP() << "this kernel has no transparent huge pages";
  }
  const int code = ExitCodeInAFreshProcess(CheckInAFreshProcess);
  ASSERT_GE(code, 0) << "the child could not start or died";
  if (code == kKernelShowsNoAdvice) {
    GTEST_SKIP() << "this kernel does not show MADV_HUGEPAGE in /proc/self/smaps";
  }
  if (code == kAdvisedBefore) GTEST_SKIP() << "glibc advises huge pages already (GLIBC_TUNABLES)";
  // 10/11/13: malloc or calloc failed; 12: no advice after; 14: calloc returned non-zeros.
  EXPECT_EQ(code, 0);
}

// Resident memory of this process, in bytes (/proc/self/statm's second field, in pages).
std::int64_t ResidentBytes() {
  std::ifstream statm("/proc/self/statm");
  std::int64_t size = 0, resident = 0;
  statm >> size >> resident;
  return resident * static_cast<std::int64_t>(sysconf(_SC_PAGESIZE));
}

// A child's exit code when this kernel cannot prefault (MADV_POPULATE_WRITE, Linux 5.14).
constexpr int kKernelCannotPrefault = 79;

// In a fresh process: without the set-up the call maps nothing; after it, the heap's first 16 MiB
// become resident on the helper thread, and blocks malloc then hands out are there, zero and
// writable.
int CheckPrefaultInAFreshProcess() {
  {
    constexpr std::size_t kSize = std::size_t{2} << 20;
    void* probe = mmap(nullptr, kSize, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (probe == MAP_FAILED) return 20;
    const bool can = madvise(probe, kSize, MADV_POPULATE_WRITE) == 0;
    munmap(probe, kSize);
    if (!can) return kKernelCannotPrefault;
  }
  constexpr std::int64_t kAsked = std::int64_t{16} << 20;
  const std::int64_t at_start = ResidentBytes();
  PrefaultHeapInBackground(kAsked);  // before the set-up: nothing to map
  usleep(200 * 1000);
  if (ResidentBytes() - at_start > kAsked / 2) return 21;
  PrepareAllocatorForOneRun();
  const std::int64_t before = ResidentBytes();
  PrefaultHeapInBackground(kAsked);
  bool mapped = false;
  for (int wait = 0; wait < 200 && !mapped; ++wait) {
    mapped = ResidentBytes() - before >= kAsked - (std::int64_t{2} << 20);
    if (!mapped) usleep(10 * 1000);
  }
  if (!mapped) return 22;
  // The mapped pages are the ones malloc hands out next (a block below the set-up's 8 MiB mmap
  // threshold comes from the heap): writing 6 MiB there adds little.
  constexpr std::size_t kBlock = std::size_t{6} << 20;
  auto* block = static_cast<unsigned char*>(std::calloc(kBlock, 1));
  if (block == nullptr) return 23;
  for (std::size_t i = 0; i < kBlock; i += 4096) {
    if (block[i] != 0) return 24;
  }
  const std::int64_t mapped_total = ResidentBytes();
  std::memset(block, 0x5a, kBlock);
  if (ResidentBytes() - mapped_total > (std::int64_t{2} << 20)) return 25;
  std::free(block);
  return 0;
}

TEST(OneRunAllocatorTest, PrefaultMapsTheHeapAheadOfTheRunOnlyAfterTheSetUp) {
  if (kSanitizerAllocator) GTEST_SKIP() << "the sanitizers replace malloc";
  if (!std::filesystem::exists("/sys/kernel/mm/transparent_hugepage")) {
    GTEST_SKIP()
        << "this kernel has no transparent huge pages, so the set-up leaves the heap alone";
  }
  const int code = ExitCodeInAFreshProcess(CheckPrefaultInAFreshProcess);
  ASSERT_GE(code, 0) << "the child could not start or died";
  if (code == kKernelCannotPrefault) {
    GTEST_SKIP() << "this kernel cannot prefault (MADV_POPULATE_WRITE)";
  }
  // 21: mapped without the set-up; 22: not mapped after it; 23: calloc failed; 24: non-zero
  // memory; 25: the block was not on the mapped pages.
  EXPECT_EQ(code, 0);
}

}  // namespace
}  // namespace getme::cli
