#pragma once

#include <string>
#include <vector>

#include "absl/status/status.h"
#include "benchmark_mesh.h"
#include "run_measurement.h"

namespace getme::bench {

// Base name of a measurement's files: "<mesh>.<method>.t<threads>[.service]".
std::string MeasurementFileStem(const Measurement& measurement);

// One JSON object: the mesh, method, threads and mode; the median repeat's result exactly as
// `getme smooth --json` prints it ("result"); median/min/max of wall time, engine time, time to
// 99 % of the q_mean gain, time to the target q_mean and peak RSS; and every repeat ("runs").
// `trace_file` is the name of the trace written beside it ("" if none).
std::string MeasurementJson(const Measurement& measurement, const BenchmarkMesh& mesh,
                            const std::string& trace_file);

// The median repeat's progress events and its result line, one JSON object per line, as
// `getme smooth --trace` writes them (so `getme report --trace` plots it).
absl::Status WriteTrace(const std::string& path, const Measurement& measurement,
                        const BenchmarkMesh& mesh);

// Markdown: one row per measurement, medians with (min–max).
std::string MarkdownSummary(const std::vector<Measurement>& measurements,
                            const std::vector<BenchmarkMesh>& meshes);

// Markdown: in-process against service median wall time for each measurement run both ways;
// empty if there is none.
std::string ServiceOverheadSummary(const std::vector<Measurement>& measurements);

}  // namespace getme::bench
