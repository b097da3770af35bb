#include "cli/jobs_command.h"

#include <unistd.h>

#include <cstdio>

#include "absl/strings/str_cat.h"
#include "cli/failure.h"
#include "cli/interrupt_scope.h"
#include "cli/mesh_files.h"
#include "cli/progress_printer.h"
#include "cli/remote_output.h"
#include "cli/server_access.h"
#include "cli/text_reports.h"
#include "events/json_events.h"
#include "getme_wire/engine_mesh.h"
#include "getme_wire/enums.h"
#include "getme_wire/progress.h"
#include "getme_wire/status.h"
#include "remote/grid_upload.h"
#include "remote/smoother_client.h"

namespace getme::cli {
namespace {

void PrintJob(const v1::Job& job, bool json) {
  std::printf("%s\n", json ? JobJson(job).c_str() : FormatJobLine(job).c_str());
}

int List(remote::SmootherClient& client, const JobsCommandOptions& options) {
  absl::StatusOr<std::vector<v1::Job>> jobs = client.ListJobs();
  if (!jobs.ok()) return ReportRemoteFailure(jobs.status(), options.json, kExitFailure);
  if (jobs->empty() && !options.json) std::printf("no jobs on %s\n", options.server.c_str());
  for (const v1::Job& job : *jobs) PrintJob(job, options.json);
  std::fflush(stdout);
  return kExitSuccess;
}

// A job that ended without success is a failure of what the user waited for.
int ReportJobOutcome(const v1::Job& job, bool json) {
  if (job.state() == v1::JOB_STATE_SUCCEEDED) return kExitSuccess;
  const absl::StatusCode code =
      job.error_code() != 0 ? wire::FromWireJobError(job).code()
                            : (job.state() == v1::JOB_STATE_CANCELLED ? absl::StatusCode::kCancelled
                                                                      : absl::StatusCode::kUnknown);
  return ReportRemoteFailure(
      absl::Status(code,
                   absl::StrCat("job ", job.job_id(), " ended ", JobStateName(job.state()),
                                job.error_message().empty() ? "" : ": ", job.error_message())),
      json, kExitFailure);
}

int Watch(remote::SmootherClient& client, const JobsCommandOptions& options) {
  ProgressPrinter printer(stderr, isatty(fileno(stderr)) != 0);
  absl::Status watched;
  bool interrupted = false;
  {
    InterruptScope interrupt;
    remote::CallOptions call;
    call.cancel = &interrupt.flag();
    watched = client.WatchJob(
        options.job_id,
        [&](const v1::ProgressEvent& wire_event) {
          // The job's closing marker repeats the state of the last phase end; it is not an engine
          // event, and local mode has no such line.
          if (wire_event.final() && !wire_event.phase_done()) return;
          if (wire_event.restarted()) {
            AnnounceRestart(wire_event, options.json);
            return;
          }
          const ProgressEvent event = wire::FromWireProgress(wire_event);
          if (options.json) {
            std::printf("%s\n", events::ProgressEventJson(event).c_str());
            std::fflush(stdout);
          } else {
            printer.OnEvent(event);
          }
        },
        call);
    interrupted = interrupt.interrupted();
  }
  printer.Finish();
  if (interrupted) {
    return ReportFailure(absl::CancelledError(absl::StrCat("stopped watching job ", options.job_id,
                                                           "; it goes on on the server")),
                         options.json, kExitInterrupted);
  }
  if (!watched.ok()) return ReportRemoteFailure(watched, options.json, kExitFailure);
  absl::StatusOr<v1::Job> job = client.GetJob(options.job_id);
  if (!job.ok()) return ReportRemoteFailure(job.status(), options.json, kExitFailure);
  PrintJob(*job, options.json);
  std::fflush(stdout);
  return ReportJobOutcome(*job, options.json);
}

int Cancel(remote::SmootherClient& client, const JobsCommandOptions& options) {
  absl::StatusOr<v1::Job> job = client.CancelJob(options.job_id);
  if (!job.ok()) return ReportRemoteFailure(job.status(), options.json, kExitFailure);
  PrintJob(*job, options.json);
  std::fflush(stdout);
  return kExitSuccess;
}

int Fetch(remote::SmootherClient& client, const JobsCommandOptions& options) {
  absl::StatusOr<formats::MeshDocument> document = ReadInputMesh(options.input, options.files);
  if (!document.ok()) return ReportFailure(document.status(), options.json, kExitFailure);
  absl::StatusOr<OutputTarget> output = ResolveOutput(*document, options.output, options.files);
  if (!output.ok()) return ReportFailure(output.status(), options.json, kExitFailure);
  const formats::UnstructuredGrid* file = &document->grid;
  absl::StatusOr<remote::GridWireMesh> sent = remote::ToWireMesh(*file);
  if (!sent.ok()) return ReportFailure(sent.status(), options.json, kExitFailure);
  // The method is only on the job; ask before fetching (a fetched result is dropped).
  absl::StatusOr<v1::Job> job = client.GetJob(options.job_id);
  if (!job.ok()) return ReportRemoteFailure(job.status(), options.json, kExitFailure);
  absl::StatusOr<remote::RemoteSmoothResult> result = client.GetResult(options.job_id);
  if (!result.ok()) return ReportRemoteFailure(result.status(), options.json, kExitFailure);
  if (result->result.nodes() != static_cast<std::uint64_t>(file->point_count())) {
    return ReportFailure(
        absl::InvalidArgumentError(absl::StrCat(
            "job ", options.job_id, " smoothed a mesh of ", result->result.nodes(), " nodes, but ",
            options.input, " has ", file->point_count(), " points; is it the submitted file?")),
        options.json, kExitFailure);
  }
  const events::SmoothReport report =
      MakeRemoteSmoothReport(options.input, options.output, wire::MethodOrGetme(job->method()),
                             *file, *sent, result->result);
  if (absl::Status status =
          WriteSmoothedFile(wire::CoordinatesOf(result->mesh), *output, *document);
      !status.ok()) {
    return ReportFailure(status, options.json, kExitFailure);
  }
  if (options.json) {
    std::printf("%s\n", events::SmoothResultJson(report).c_str());
  } else {
    std::fputs(FormatSmoothSummary(report).c_str(), stdout);
  }
  std::fflush(stdout);
  return kExitSuccess;
}

}  // namespace

int RunJobsCommand(const JobsCommandOptions& options) {
  absl::StatusOr<std::shared_ptr<grpc::Channel>> channel =
      OpenServerChannel(options.server, options.access);
  if (!channel.ok()) return ReportFailure(channel.status(), options.json, kExitFailure);
  remote::SmootherClient client(*std::move(channel));
  switch (options.action) {
    case JobsAction::kList:
      return List(client, options);
    case JobsAction::kWatch:
      return Watch(client, options);
    case JobsAction::kCancel:
      return Cancel(client, options);
    case JobsAction::kFetch:
      break;
  }
  return Fetch(client, options);
}

}  // namespace getme::cli
