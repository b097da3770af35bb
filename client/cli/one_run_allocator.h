#pragma once

#include <cstddef>

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

// Maps the first `bytes` of the heap that PrepareAllocatorForOneRun set up, on a thread of its
// own, ahead of the run that will use them. A first touch of a page costs the thread that makes
// it; the reading and building of a mesh run on one thread while the other core waits, and on
// this project's VM first touches were a third of reading cub_wedge_like.vtk (docs/benchmarks.md,
// "Before the engine, and two set-up costs in it"). Does nothing where that set-up did not
// happen or the kernel cannot prefault (MADV_POPULATE_WRITE, Linux 5.14). Costs `bytes` of
// resident memory whether the run uses them or not, so ask for what the run will use.
void PrefaultHeapInBackground(std::size_t bytes);

}  // namespace getme::cli
