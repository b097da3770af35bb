#pragma once

#include "cli/cli_options.h"

namespace getme::cli {

// `getme quality`: read, convert, evaluate with getme::EvaluateMeshQuality, report on stdout.
// Returns the exit status (failure.h).
int RunQualityCommand(const QualityCommandOptions& options);

}  // namespace getme::cli
