#pragma once

namespace getme::cli {

// Sets the C library's allocator up for a process that runs one job and exits: memory it frees
// stays in the process for the next allocation, and the heap is backed by 2 MiB transparent huge
// pages where the kernel offers them (madvise mode). A run builds the mesh, its smoothing buffers
// and its output text once each, so nearly every page it touches is touched for the first time;
// on a virtual machine a first touch costs microseconds, and page faults were 12–17 % of a whole
// small run (docs/benchmarks.md, "Page faults of a one-shot run"). Call it first in main, before
// any thread starts; it changes where memory comes from, never what a run computes. Not for the
// server, which should give memory back between jobs.
void PrepareAllocatorForOneRun();

}  // namespace getme::cli
