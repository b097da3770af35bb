#pragma once

#include "cli/cli_options.h"

namespace getme::cli {

// `getme smooth`: read, convert, smooth in-process with getme::Smooth, write the file with the
// smoothed coordinates and quality arrays, report. Progress goes to stderr (human) or stdout
// (JSON lines); the result to stdout. Ctrl-C cancels the smoothing cleanly and writes nothing.
// Returns the exit status (failure.h).
int RunSmoothCommand(const SmoothCommandOptions& options);

}  // namespace getme::cli
