#pragma once

#include <optional>
#include <span>
#include <string>

#include "absl/status/status.h"
#include "cli/mesh_files.h"
#include "events/reports.h"
#include "formats/unstructured_grid.h"
#include "getme/smoothing/smoothing_params.h"
#include "getme/v1/smoother.pb.h"
#include "remote/grid_upload.h"

namespace getme::cli {

// What the remote modes share with each other and with the local output.

// Puts the smoothed coordinates into the document, recomputes the per-cell quality arrays
// exactly as the local mode does (so a remote run writes the same file), and writes it.
absl::Status WriteSmoothedFile(std::span<const double> coordinates, const OutputTarget& output,
                               formats::MeshDocument& document);

// The report of a remote smoothing run, filled from the wire result and the sent mesh: the
// boundary the job ran with and its surface and layer reports as well, so that `jobs fetch`,
// which knows nothing of the job's parameters, reports them as `smooth --server` does.
events::SmoothReport MakeRemoteSmoothReport(const std::string& input, const std::string& output,
                                            Method method, const formats::UnstructuredGrid& file,
                                            const remote::GridWireMesh& sent,
                                            const v1::SmoothResult& result);

// "QUEUED", "RUNNING", … as the CLI prints job states.
const char* JobStateName(v1::JobState state);
// {"event":"job","job_id":…,"state":"RUNNING",…} and its one-line text form.
std::string JobJson(const v1::Job& job);
std::string FormatJobLine(const v1::Job& job);
// A `restarted` event (replicas sharing a job store: the replica running the job was lost and
// another starts it again): {"event":"restarted","job_id":…,"attempt":N} on stdout with --json,
// else a line on stderr. The progress that follows is the new attempt's, from its first phase.
void AnnounceRestart(const v1::ProgressEvent& event, bool json);

}  // namespace getme::cli
