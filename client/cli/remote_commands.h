#pragma once

#include "cli/cli_options.h"

namespace getme::cli {

// `getme smooth --server HOST:PORT`: the file is converted without local validation (the server
// names what is wrong), uploaded in chunks, smoothed on the server with the same progress display
// and JSON lines as the local mode, and the returned coordinates are written with the quality
// arrays recomputed, so the output file equals the local one. Ctrl-C cancels the job on the
// server. With --detach the job is only queued and its id printed. Returns the exit status.
int RunRemoteSmoothCommand(const SmoothCommandOptions& options);

// `getme quality --server HOST:PORT`: EvaluateQuality on the server, same report as local.
int RunRemoteQualityCommand(const QualityCommandOptions& options);

}  // namespace getme::cli
