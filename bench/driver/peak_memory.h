#pragma once

#include <sys/types.h>

#include <cstdint>
#include <optional>

namespace getme::bench {

// Peak resident set size of a run (Linux). getrusage's ru_maxrss is the high-water mark of the
// whole process, so loading the mesh (a file document, a gmsh session) would dominate it; writing
// "5" to /proc/PID/clear_refs resets that mark to the current RSS first, so the peak after the
// run is the run's own (mesh + engine), not the loader's.
bool ResetPeakRss(pid_t pid = 0);  // 0: this process. False when the kernel refuses.
std::int64_t PeakRssBytes();       // this process, getrusage(RUSAGE_SELF)
std::int64_t CurrentRssBytes();    // this process, /proc/self/statm
// Another process's peak (VmHWM of /proc/PID/status), e.g. a getme-server this program started.
std::optional<std::int64_t> ProcessPeakRssBytes(pid_t pid);

}  // namespace getme::bench
