// getme: the local command-line front end. Dispatches to the subcommands; everything else lives
// in the getme_cli library so the gRPC client can reuse it. Built twice (client/CMakeLists.txt):
// `getme` without the service, which hands the commands that need a server to `getme-remote`,
// built from this same file with GETME_WITH_SERVICE.

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <filesystem>
#include <string>
#include <system_error>
#include <vector>

#include "absl/status/status.h"
#include "absl/strings/str_cat.h"
#include "cli/cli_options.h"
#include "cli/convert_command.h"
#include "cli/failure.h"
#include "cli/one_run_allocator.h"
#include "cli/quality_command.h"
#include "cli/report_command.h"
#include "cli/smooth_command.h"
#ifdef GETME_WITH_SERVICE
#include "cli/jobs_command.h"
#include "cli/remote_commands.h"
#endif
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

#ifndef GETME_WITH_SERVICE
// --server and `getme jobs`: run by getme-remote, from getme's own directory, with the same
// arguments, in place of this process (so its exit status, signals and output are the user's).
int RunWithTheService(char** argv, bool json) {
#ifdef GETME_REMOTE_BINARY
  std::error_code error;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", error);
  const std::string remote = error ? std::string(GETME_REMOTE_BINARY)
                                   : (self.parent_path() / GETME_REMOTE_BINARY).string();
  std::fflush(nullptr);
  execv(remote.c_str(), argv);  // returns only when it cannot run
  const int exec_error = errno;
  return getme::cli::ReportFailure(
      absl::FailedPreconditionError(
          absl::StrCat("--server and 'getme jobs' run in ", remote,
                       ", which cannot be started: ", std::generic_category().message(exec_error))),
      json, getme::cli::kExitFailure);
#else
  (void)argv;
  return getme::cli::ReportFailure(
      absl::UnimplementedError("this getme was built without the gRPC service "
                               "(GETME_BUILD_SERVICE=OFF): --server and 'getme jobs' are "
                               "unavailable"),
      json, getme::cli::kExitUsage);
#endif
}
#endif

}  // namespace

int main(int argc, char** argv) {
  getme::cli::PrepareAllocatorForOneRun();
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
    if (!args.empty() && args.front() == "jobs") return PrintUsage(getme::cli::kJobsUsage);
    if (!args.empty() && args.front() == "report") return PrintUsage(getme::cli::kReportUsage);
    if (!args.empty() && args.front() == "convert") return PrintUsage(getme::cli::kConvertUsage);
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
    if (!options->server.empty()) {
#ifdef GETME_WITH_SERVICE
      return getme::cli::RunRemoteSmoothCommand(*options);
#else
      return RunWithTheService(argv, json);
#endif
    }
    return getme::cli::RunSmoothCommand(*options);
  }
  if (command == "quality") {
    absl::StatusOr<getme::cli::QualityCommandOptions> options =
        getme::cli::ParseQualityArguments(args);
    if (!options.ok()) return getme::cli::ReportFailure(options.status(), json, kExitUsage);
    if (options->help) return PrintUsage(getme::cli::kQualityUsage);
    ConfigureLogging(/*quiet=*/true);
    if (!options->server.empty()) {
#ifdef GETME_WITH_SERVICE
      return getme::cli::RunRemoteQualityCommand(*options);
#else
      return RunWithTheService(argv, json);
#endif
    }
    return getme::cli::RunQualityCommand(*options);
  }
  if (command == "report") {
    absl::StatusOr<getme::cli::ReportCommandOptions> options =
        getme::cli::ParseReportArguments(args);
    if (!options.ok()) return getme::cli::ReportFailure(options.status(), json, kExitUsage);
    if (options->help) return PrintUsage(getme::cli::kReportUsage);
    ConfigureLogging(/*quiet=*/false);
    return getme::cli::RunReportCommand(*options);
  }
  if (command == "convert") {
    absl::StatusOr<getme::cli::ConvertCommandOptions> options =
        getme::cli::ParseConvertArguments(args);
    if (!options.ok()) return getme::cli::ReportFailure(options.status(), json, kExitUsage);
    if (options->help) return PrintUsage(getme::cli::kConvertUsage);
    ConfigureLogging(/*quiet=*/false);
    return getme::cli::RunConvertCommand(*options);
  }
  if (command == "jobs") {
    absl::StatusOr<getme::cli::JobsCommandOptions> options = getme::cli::ParseJobsArguments(args);
    if (!options.ok()) return getme::cli::ReportFailure(options.status(), json, kExitUsage);
    if (options->help) return PrintUsage(getme::cli::kJobsUsage);
    ConfigureLogging(/*quiet=*/true);
#ifdef GETME_WITH_SERVICE
    return getme::cli::RunJobsCommand(*options);
#else
    return RunWithTheService(argv, json);
#endif
  }
  return getme::cli::ReportFailure(
      absl::InvalidArgumentError(
          absl::StrCat("unknown command '", command,
                       "'; expected 'smooth', 'quality', 'report', 'convert' or 'jobs' (see "
                       "'getme --help')")),
      json, kExitUsage);
}
