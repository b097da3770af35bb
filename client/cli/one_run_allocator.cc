#include "cli/one_run_allocator.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <thread>

#if defined(__GLIBC__) && defined(__linux__)
#include <malloc.h>
#include <sys/mman.h>
#include <unistd.h>
#endif

namespace getme::cli {

#if defined(__GLIBC__) && defined(__linux__)
namespace {

// Blocks up to this size come from the heap, and stay there when freed; larger ones (the arrays
// of meshes of a few hundred thousand elements and more) keep their own mappings and go back to
// the system when freed. With the growth below it bounds what the process keeps that it no longer
// uses: at 1.09M elements the peak RSS stayed at 313 MB (315 MB without this set-up), where 32 MiB
// and 256 MiB gave 384 MB (docs/benchmarks.md, "Page faults of a one-shot run").
constexpr int kLargestHeapBlock = 8 << 20;
// Address space taken with every growth of the heap, and the free space at its top kept when
// blocks are freed. The first growth is the one that gets huge pages; untouched, it costs neither
// memory nor time.
constexpr int kHeapGrowth = 64 << 20;
constexpr std::uintptr_t kHugePage = std::uintptr_t{2} << 20;
// glibc's chunk header: the size field before a block, and the previous chunk's size before it.
constexpr std::uintptr_t kChunkHeader = 2 * sizeof(std::size_t);

// The huge-page part of the heap that PrepareAllocatorForOneRun set up, [begin, end); empty when
// it set none up.
std::uintptr_t huge_begin = 0;
std::uintptr_t huge_end = 0;

std::uintptr_t Break() { return reinterpret_cast<std::uintptr_t>(sbrk(0)); }
std::uintptr_t RoundUp(std::uintptr_t address) {
  return (address + kHugePage - 1) & ~(kHugePage - 1);
}

}  // namespace

void PrepareAllocatorForOneRun() {
  // Freed memory is reused, not returned: the free and re-touch of the same pages between phases
  // (the parser's arrays, then the builder's, then the writer's text) is what this saves.
  mallopt(M_TRIM_THRESHOLD, 1 << 30);
  mallopt(M_MMAP_THRESHOLD, kLargestHeapBlock);
  mallopt(M_TOP_PAD, kHeapGrowth);
  // Grow the heap now, by kHeapGrowth: a block larger than what is free at its top, given back.
  const std::uintptr_t old_break = Break();
  void* volatile probe = std::malloc(1 << 20);  // volatile: the pair must not be optimised away
  std::free(probe);
  const std::uintptr_t new_break = Break();
  if (new_break <= old_break) return;  // the heap could not grow; malloc works as before
  // From the header of the heap's top chunk (the free space up to the break, `keepcost` before
  // any thread has an arena of its own) to the break, the allocator keeps nothing.
  const std::uintptr_t top = new_break - mallinfo2().keepcost;
  const std::uintptr_t begin = RoundUp(std::max(old_break, top + kChunkHeader));
  const std::uintptr_t end = new_break & ~(kHugePage - 1);
  if (end <= begin) return;
  // Growing the heap wrote a header above the probe, perhaps in [begin, end): dropping those
  // pages (they read as zeros again, as fresh heap does) lets the first touch of every 2 MiB
  // there be a huge page. Where the kernel offers none, the advice fails and changes nothing.
  madvise(reinterpret_cast<void*>(begin), end - begin, MADV_DONTNEED);
  if (madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE) != 0) return;
  huge_begin = begin;
  huge_end = end;
  // Start the run's blocks at `begin`: the few hundred kilobytes below it stay allocated and
  // untouched for the process's life, so no block straddles small and huge pages.
  if (begin - top > 4 * kChunkHeader) {
    [[maybe_unused]] void* volatile spacer = std::malloc(begin - top - 2 * kChunkHeader);
  }
}

void PrefaultHeapInBackground(std::size_t bytes) {
  if (huge_begin == 0) return;
  const std::uintptr_t end =
      std::min(huge_end, huge_begin + ((bytes + kHugePage - 1) & ~(kHugePage - 1)));
  if (end <= huge_begin) return;
  // Detached: the process may end before it does, which is harmless (it only maps pages). The
  // advice maps what malloc has not handed out yet or is handing out right now; the kernel maps
  // each page once, whichever thread comes first, and never touches its contents after.
  std::thread([begin = huge_begin, end] {
    for (std::uintptr_t at = begin; at < end; at += kHugePage) {
      if (madvise(reinterpret_cast<void*>(at), kHugePage, MADV_POPULATE_WRITE) != 0) return;
    }
  }).detach();
}

#else

void PrepareAllocatorForOneRun() {}
void PrefaultHeapInBackground(std::size_t) {}

#endif

}  // namespace getme::cli
