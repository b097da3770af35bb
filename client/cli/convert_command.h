#pragma once

#include "cli/cli_options.h"

namespace getme::cli {

// `getme convert IN OUT`: returns the exit status.
int RunConvertCommand(const ConvertCommandOptions& options);

}  // namespace getme::cli
