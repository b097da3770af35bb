#pragma once

#include <string>

#include "absl/status/status.h"
#include "events/reports.h"
#include "getme/smoothing/progress.h"

namespace getme::events {

// The JSON lines of `getme smooth --json` and `getme quality --json`, one object each:
// {"event":"progress",…} per progress event, {"event":"result",…} at the end, {"event":"error",
// "code":"INVALID_ARGUMENT","message":…} on failure, {"event":"quality",…} for `quality`.
std::string ProgressEventJson(const ProgressEvent& event);
std::string SmoothResultJson(const SmoothReport& report);
std::string QualityReportJson(const QualityReport& report);
std::string ErrorJson(const absl::Status& status);

}  // namespace getme::events
