#include "getme_server/process_memory.h"

#include <unistd.h>

#include <fstream>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace getme::server {

ProcessMemory ReadProcessMemory() {
  ProcessMemory memory;
  // statm: size resident shared ... in pages.
  std::ifstream statm("/proc/self/statm");
  std::int64_t size_pages = 0;
  std::int64_t resident_pages = 0;
  if (statm >> size_pages >> resident_pages) {
    memory.resident_bytes = resident_pages * sysconf(_SC_PAGESIZE);
  }
#if defined(__GLIBC__)
  if constexpr (kHeapCountsKnown) {
    const struct mallinfo2 info = mallinfo2();
    // uordblks: in use in the arenas; hblkhd: blocks large enough to get their own mapping.
    memory.heap_in_use_bytes = static_cast<std::int64_t>(info.uordblks + info.hblkhd);
  }
#endif
  return memory;
}

void ReleaseFreedHeapMemory() {
#if defined(__GLIBC__)
  malloc_trim(0);
#endif
}

}  // namespace getme::server
