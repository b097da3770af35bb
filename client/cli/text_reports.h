#pragma once

#include <string>

#include "events/reports.h"
#include "getme/smoothing/progress.h"

namespace getme::cli {

// Human-readable output of the CLI (and later of the gRPC client).

// "simultaneous  iteration 12  q_min 0.412345  q_mean 0.812345  invalid 0  1.2 s"
std::string FormatProgressLine(const ProgressEvent& event);

// The before/after table of `getme smooth`: nodes, elements per type, q_min, q_mean, invalid,
// warpage, then iterations and seconds per phase, total seconds and threads.
std::string FormatSmoothSummary(const events::SmoothReport& report);

// The report of `getme quality`: counts, q_min/q_mean per type and overall, invalid elements,
// warpage, histogram.
std::string FormatQualityReport(const events::QualityReport& report);

}  // namespace getme::cli
