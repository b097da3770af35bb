#pragma once

#include "cli/cli_options.h"

namespace getme::cli {

// `getme jobs list|watch|cancel|fetch` against a getme-server. Returns the exit status.
int RunJobsCommand(const JobsCommandOptions& options);

}  // namespace getme::cli
