#pragma once

#include "cli/cli_options.h"

namespace getme::cli {

// `getme report`: quality pictures of a smoothing run (gnuplot). Returns the exit status.
int RunReportCommand(const ReportCommandOptions& options);

}  // namespace getme::cli
