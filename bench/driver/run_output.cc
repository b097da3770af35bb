#include "run_output.h"

#include <functional>
#include <optional>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_format.h"
#include "events/json_events.h"
#include "events/json_output.h"
#include "events/reports.h"
#include "events/trace_file.h"

namespace getme::bench {
namespace {

using RepeatValue = std::function<std::optional<double>(const RunMeasurement&)>;

// The spread of a value over the repeats, or none if some repeat lacks it.
std::optional<Spread> SpreadOver(const Measurement& measurement, const RepeatValue& value) {
  std::vector<double> values;
  for (const RunMeasurement& repeat : measurement.repeats) {
    const std::optional<double> v = value(repeat);
    if (!v.has_value()) return std::nullopt;
    values.push_back(*v);
  }
  return SpreadOf(std::move(values));
}

std::string SpreadJson(const std::optional<Spread>& spread) {
  if (!spread.has_value()) return "null";
  return events::JsonObject()
      .AddDouble("median", spread->median)
      .AddDouble("min", spread->min)
      .AddDouble("max", spread->max)
      .Build();
}

std::string OptionalJson(const std::optional<double>& value) {
  return value.has_value() ? events::JsonNumber(*value) : "null";
}

const RepeatValue kWall = [](const RunMeasurement& r) { return r.wall_seconds; };
const RepeatValue kEngine = [](const RunMeasurement& r) { return r.result.seconds; };
const RepeatValue kTo99 = [](const RunMeasurement& r) { return r.seconds_to_99_percent_gain; };
const RepeatValue kToTarget = [](const RunMeasurement& r) { return r.seconds_to_target; };
const RepeatValue kPeakRss = [](const RunMeasurement& r) {
  return static_cast<double>(r.peak_rss_bytes);
};
const RepeatValue kServerPeakRss = [](const RunMeasurement& r) -> std::optional<double> {
  if (!r.server_peak_rss_bytes.has_value()) return std::nullopt;
  return static_cast<double>(*r.server_peak_rss_bytes);
};

events::SmoothReport ReportOf(const RunMeasurement& run, const Measurement& measurement,
                              const BenchmarkMesh& mesh) {
  events::SmoothReport report;
  report.input = mesh.spec.path_or_arguments;
  report.method = measurement.method;
  report.nodes = mesh.mesh.node_count();
  for (const ElementType type : kAllElementTypes) {
    report.elements_by_type[TypeIndex(type)] = mesh.mesh.element_count(type);
  }
  report.result = run.result;
  return report;
}

std::string RepeatJson(const RunMeasurement& run) {
  return events::JsonObject()
      .AddDouble("wall_seconds", run.wall_seconds)
      .AddDouble("engine_seconds", run.result.seconds)
      .AddRaw("seconds_to_99_percent_gain", OptionalJson(run.seconds_to_99_percent_gain))
      .AddRaw("seconds_to_target", OptionalJson(run.seconds_to_target))
      .AddInt("peak_rss_bytes", run.peak_rss_bytes)
      .AddBool("peak_rss_reset", run.peak_rss_reset)
      .AddRaw("server_peak_rss_bytes", run.server_peak_rss_bytes.has_value()
                                           ? absl::StrCat(*run.server_peak_rss_bytes)
                                           : "null")
      .AddRaw("first_event_wall_seconds", OptionalJson(run.first_event_wall_seconds))
      .AddInt("progress_events", static_cast<std::int64_t>(run.trace.size()))
      .AddDouble("q_min", run.result.after.q_min)
      .AddDouble("q_mean", run.result.after.q_mean)
      .Build();
}

std::string Seconds(const std::optional<Spread>& spread) {
  if (!spread.has_value()) return "–";
  if (spread->min == spread->max) return absl::StrFormat("%.3f", spread->median);
  return absl::StrFormat("%.3f (%.3f–%.3f)", spread->median, spread->min, spread->max);
}

const BenchmarkMesh* FindMesh(const std::vector<BenchmarkMesh>& meshes, const std::string& name) {
  for (const BenchmarkMesh& mesh : meshes) {
    if (mesh.spec.name == name) return &mesh;
  }
  return nullptr;
}

}  // namespace

std::string MeasurementFileStem(const Measurement& measurement) {
  return absl::StrCat(measurement.mesh, ".", MethodName(measurement.method), ".t",
                      measurement.threads, measurement.mode == RunMode::kService ? ".service" : "");
}

std::string MeasurementJson(const Measurement& measurement, const BenchmarkMesh& mesh,
                            const std::string& trace_file) {
  if (measurement.repeats.empty()) {
    return events::JsonObject()
        .AddString("mesh", measurement.mesh)
        .AddString("spec", mesh.spec.path_or_arguments)
        .AddString("method", MethodName(measurement.method))
        .AddInt("threads", measurement.threads)
        .AddString("mode", RunModeName(measurement.mode))
        .AddString("error", measurement.error)
        .Build();
  }
  const RunMeasurement& median = measurement.repeats[MedianRepeat(measurement)];
  events::JsonObject by_type;
  for (const ElementType type : kAllElementTypes) {
    by_type.AddInt(TypeName(type), mesh.mesh.element_count(type));
  }
  std::string runs = "[";
  for (std::size_t i = 0; i < measurement.repeats.size(); ++i) {
    absl::StrAppend(&runs, i > 0 ? "," : "", RepeatJson(measurement.repeats[i]));
  }
  runs += "]";
  return events::JsonObject()
      .AddString("mesh", measurement.mesh)
      .AddString("source", mesh.spec.source == MeshSpec::Source::kFile ? "file" : "generator")
      .AddString("spec", mesh.spec.path_or_arguments)
      .AddInt("nodes", mesh.mesh.node_count())
      .AddInt("elements", mesh.mesh.element_count())
      .AddRaw("elements_by_type", by_type.Build())
      .AddDouble("load_seconds", mesh.load_seconds)
      .AddInt("rss_before_load_bytes", mesh.rss_before_load_bytes)
      .AddInt("rss_after_load_bytes", mesh.rss_after_load_bytes)
      .AddString("method", MethodName(measurement.method))
      .AddInt("threads", measurement.threads)
      // The element passes' width an in-process run used; a server's runs choose their own.
      .AddRaw("kernel_lanes", measurement.mode == RunMode::kInProcess
                                  ? absl::StrCat(median.result.kernel_lanes)
                                  : "null")
      .AddString("mode", RunModeName(measurement.mode))
      .AddInt("repeats", static_cast<std::int64_t>(measurement.repeats.size()))
      .AddBool("repeats_agree", RepeatsAgree(measurement))
      .AddRaw("target_q_mean", OptionalJson(measurement.target_q_mean))
      .AddString("smoothing_options", measurement.smoothing_options)
      .AddRaw("wall_seconds", SpreadJson(SpreadOver(measurement, kWall)))
      .AddRaw("engine_seconds", SpreadJson(SpreadOver(measurement, kEngine)))
      .AddRaw("seconds_to_99_percent_gain", SpreadJson(SpreadOver(measurement, kTo99)))
      .AddRaw("seconds_to_target", SpreadJson(SpreadOver(measurement, kToTarget)))
      .AddRaw("peak_rss_bytes", SpreadJson(SpreadOver(measurement, kPeakRss)))
      .AddRaw("server_peak_rss_bytes", SpreadJson(SpreadOver(measurement, kServerPeakRss)))
      .AddString("trace", trace_file)
      .AddRaw("result", events::SmoothResultJson(ReportOf(median, measurement, mesh)))
      .AddRaw("runs", runs)
      .Build();
}

absl::Status WriteTrace(const std::string& path, const Measurement& measurement,
                        const BenchmarkMesh& mesh) {
  absl::StatusOr<std::unique_ptr<events::TraceFile>> trace = events::TraceFile::Open(path);
  if (!trace.ok()) return trace.status();
  const RunMeasurement& median = measurement.repeats[MedianRepeat(measurement)];
  for (const ProgressEvent& event : median.trace)
    (*trace)->WriteLine(events::ProgressEventJson(event));
  (*trace)->WriteLine(events::SmoothResultJson(ReportOf(median, measurement, mesh)));
  return (*trace)->Close();
}

std::string MarkdownSummary(const std::vector<Measurement>& measurements,
                            const std::vector<BenchmarkMesh>& meshes) {
  std::string table =
      "| mesh | elements | method | threads | mode | iterations "
      "(untangle/sim./seq./Laplace/polish) | "
      "q_min before → after | q_mean before → after | w_max / w_mean after | wall s, median "
      "(min–max) | s to 99 % gain | s to target | peak RSS MB |\n"
      "|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const Measurement& measurement : measurements) {
    if (measurement.repeats.empty()) {
      absl::StrAppendFormat(&table, "| %s | | %s | %d | %s | failed: %s ||||||||\n",
                            measurement.mesh, MethodName(measurement.method), measurement.threads,
                            RunModeName(measurement.mode), measurement.error);
      continue;
    }
    const RunMeasurement& median = measurement.repeats[MedianRepeat(measurement)];
    const SmoothingResult& result = median.result;
    const BenchmarkMesh* mesh = FindMesh(meshes, measurement.mesh);
    const std::optional<Spread> rss = SpreadOver(measurement, kPeakRss);
    absl::StrAppendFormat(
        &table,
        "| %s | %d | %s | %d | %s | %d/%d/%d/%d/%d | %.4f → %.4f | %.4f → %.4f | %.4f / %.4f "
        "| %s | %s | %s | %.0f |%s\n",
        measurement.mesh, mesh != nullptr ? mesh->mesh.element_count() : 0,
        MethodName(measurement.method), measurement.threads, RunModeName(measurement.mode),
        result.iterations_untangle, result.iterations_simultaneous, result.iterations_sequential,
        result.iterations_laplace, result.iterations_polish, result.before.q_min,
        result.after.q_min, result.before.q_mean, result.after.q_mean, result.after.warpage_max,
        result.after.warpage_mean, Seconds(SpreadOver(measurement, kWall)),
        Seconds(SpreadOver(measurement, kTo99)), Seconds(SpreadOver(measurement, kToTarget)),
        rss.has_value() ? rss->median / 1e6 : 0.0,
        RepeatsAgree(measurement) ? "" : " repeats differ!");
  }
  return table;
}

std::string ServiceOverheadSummary(const std::vector<Measurement>& measurements) {
  std::string table;
  for (const Measurement& service : measurements) {
    if (service.mode != RunMode::kService || service.repeats.empty()) continue;
    for (const Measurement& local : measurements) {
      if (local.mode != RunMode::kInProcess || local.repeats.empty() ||
          local.mesh != service.mesh || local.method != service.method ||
          local.threads != service.threads) {
        continue;
      }
      const double local_wall = SpreadOver(local, kWall)->median;
      const double service_wall = SpreadOver(service, kWall)->median;
      if (table.empty()) {
        table =
            "| mesh | method | threads | in-process wall s | service wall s | overhead |\n"
            "|---|---|---|---|---|---|\n";
      }
      absl::StrAppendFormat(&table, "| %s | %s | %d | %.3f | %.3f | %+.1f %% |\n", service.mesh,
                            MethodName(service.method), service.threads, local_wall, service_wall,
                            100.0 * (service_wall / local_wall - 1.0));
    }
  }
  return table;
}

}  // namespace getme::bench
