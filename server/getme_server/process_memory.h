#pragma once

#include <cstdint>

// Under a sanitizer its own allocator serves malloc, and glibc's counts say nothing of it.
#include "getme_support/sanitizer_allocator.h"

namespace getme::server {

#if defined(__GLIBC__) && !defined(GETME_SANITIZER_ALLOCATOR)
inline constexpr bool kHeapCountsKnown = true;
#else
inline constexpr bool kHeapCountsKnown = false;
#endif

// What GET /metrics reports of the process's memory. A leak shows in heap_in_use_bytes; resident
// memory also holds what the allocator keeps for reuse, so it moves with fragmentation too.
struct ProcessMemory {
  std::int64_t resident_bytes = -1;  // -1: not known (no /proc)
  // Bytes malloc has handed out and not got back; -1 unless kHeapCountsKnown.
  std::int64_t heap_in_use_bytes = -1;
};

ProcessMemory ReadProcessMemory();

// Hands the allocator's free pages back to the system. glibc keeps what a finished job freed
// (a mesh, its copies, the result) for reuse, and after one large free it serves later large
// blocks from the heap instead of fresh mappings; a server that smooths big meshes in bursts
// would hold its peak footprint for good. Called when a job ends and when old jobs are
// forgotten; about a millisecond. A no-op with other C libraries.
void ReleaseFreedHeapMemory();

}  // namespace getme::server
