// The server's view of its memory (GET /metrics) and its hand-back of freed heap after jobs.
#include "getme_server/process_memory.h"

#include <cstring>
#include <memory>
#include <vector>

#include "gtest/gtest.h"

namespace getme::server::testing {
namespace {

constexpr std::int64_t kMiB = 1 << 20;

// 128 MiB in 64 KiB blocks come from the heap (below glibc's mmap threshold); every other one
// is freed. Each freed block lies between blocks still in use, so it cannot merge into the heap's
// top or free a whole heap: free() keeps its pages resident until ReleaseFreedHeapMemory hands
// them back.
TEST(ProcessMemoryTest, ReleaseFreedHeapMemoryHandsFreedHeapPagesBack) {
  if constexpr (!kHeapCountsKnown) GTEST_SKIP() << "a sanitizer's allocator serves malloc";
  constexpr int kBlocks = 2048;
  constexpr std::size_t kBlockBytes = 64 << 10;
  ReleaseFreedHeapMemory();  // earlier tests' freed pages would serve these blocks unseen
  const ProcessMemory before = ReadProcessMemory();
  std::vector<std::unique_ptr<char[]>> blocks(kBlocks);
  for (auto& block : blocks) {
    block = std::make_unique_for_overwrite<char[]>(kBlockBytes);
    std::memset(block.get(), 1, kBlockBytes);
  }
  const ProcessMemory holding = ReadProcessMemory();
  EXPECT_GE(holding.heap_in_use_bytes - before.heap_in_use_bytes, 128 * kMiB);
  for (int i = 0; i < kBlocks; i += 2) blocks[i].reset();  // the last block stays
  const ProcessMemory freed = ReadProcessMemory();
  EXPECT_NEAR(static_cast<double>(holding.heap_in_use_bytes - freed.heap_in_use_bytes), 64.0 * kMiB,
              1.0 * kMiB);
  // The premise: without the hand-back the freed pages are still resident.
  ASSERT_GE(freed.resident_bytes, holding.resident_bytes - 8 * kMiB);

  ReleaseFreedHeapMemory();
  const ProcessMemory trimmed = ReadProcessMemory();
  EXPECT_LE(trimmed.resident_bytes, freed.resident_bytes - 56 * kMiB);
}

}  // namespace
}  // namespace getme::server::testing
