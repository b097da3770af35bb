// getme: the local command-line front end. Dispatches to the subcommands; everything else lives
// in the getme_cli library so the gRPC client can reuse it.

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include "absl/status/status.h"
#include "absl/strings/str_cat.h"
#include "cli/cli_options.h"
#include "cli/failure.h"
#include "cli/quality_command.h"
#include "cli/smooth_command.h"
#include "spdlog/sinks/stdout_sinks.h"
#include "spdlog/spdlog.h"

namespace {

using getme::cli::kExitSuccess;
using getme::cli::kExitUsage;

// Logs go to stderr ("[info] read …"); stdout is reserved for results (and JSON lines).
void ConfigureLogging(bool quiet) {
  auto logger = spdlog::stderr_logger_mt("getme");
  logger->set_pattern("[%l] %v");
  logger->set_level(quiet ? spdlog::level::warn : spdlog::level::info);
  spdlog::set_default_logger(logger);
}

bool Contains(const std::vector<std::string>& args, const std::string& flag) {
  return std::find(args.begin(), args.end(), flag) != args.end();
}

int PrintUsage(const char* usage) {
  std::fputs(usage, stdout);
  return kExitSuccess;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> args(argv + 1, argv + argc);
  // A usage error is reported as JSON too when --json was asked for anywhere.
  const bool json = Contains(args, "--json");
  if (args.empty()) {
    std::fputs(getme::cli::kMainUsage, stderr);
    return kExitUsage;
  }
  const std::string command = args.front();
  args.erase(args.begin());
  if (command == "-h" || command == "--help" || command == "help") {
    if (!args.empty() && args.front() == "smooth") return PrintUsage(getme::cli::kSmoothUsage);
    if (!args.empty() && args.front() == "quality") return PrintUsage(getme::cli::kQualityUsage);
    return PrintUsage(getme::cli::kMainUsage);
  }
  if (command == "--version") {
    std::printf("getme %s\n", GETME_VERSION);
    return kExitSuccess;
  }
  if (command == "smooth") {
    absl::StatusOr<getme::cli::SmoothCommandOptions> options =
        getme::cli::ParseSmoothArguments(args);
    if (!options.ok()) return getme::cli::ReportFailure(options.status(), json, kExitUsage);
    if (options->help) return PrintUsage(getme::cli::kSmoothUsage);
    ConfigureLogging(options->quiet);
    return getme::cli::RunSmoothCommand(*options);
  }
  if (command == "quality") {
    absl::StatusOr<getme::cli::QualityCommandOptions> options =
        getme::cli::ParseQualityArguments(args);
    if (!options.ok()) return getme::cli::ReportFailure(options.status(), json, kExitUsage);
    if (options->help) return PrintUsage(getme::cli::kQualityUsage);
    ConfigureLogging(/*quiet=*/true);
    return getme::cli::RunQualityCommand(*options);
  }
  return getme::cli::ReportFailure(
      absl::InvalidArgumentError(absl::StrCat("unknown command '", command,
                                              "'; expected 'smooth' or 'quality' (see 'getme "
                                              "--help')")),
      json, kExitUsage);
}
