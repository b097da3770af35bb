// getme-bench: whole smoothing runs per mesh and method, repeated, with medians, traces and peak
// memory, in-process and optionally through a getme-server (docs/benchmarks.md shows how
// bench/run.sh uses it).

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_format.h"
#include "absl/strings/str_join.h"
#include "bench_options.h"
#include "benchmark_mesh.h"
#include "cmdline/smoothing_flags.h"
#include "formats/grid_mesh.h"
#include "formats/vtk_writer.h"
#include "in_process_run.h"
#include "run_measurement.h"
#include "run_output.h"

#ifdef GETME_BENCH_WITH_SERVICE
#include "server_process.h"
#include "service_run.h"
#endif

namespace getme::bench {
namespace {

using RunFunction = std::function<absl::StatusOr<RunMeasurement>(BenchmarkMesh&)>;

std::string SmoothingOptionsText(const BenchOptions& options) {
  std::vector<std::string> flags;
  if (options.free_boundary) flags.push_back("--free-boundary");
  if (options.literal) flags.push_back("--literal");
  if (options.no_polish) flags.push_back("--no-polish");
  if (options.max_iterations.has_value()) {
    flags.push_back(absl::StrCat("--max-iterations ", *options.max_iterations));
  }
  if (options.sequential_batch > 0) {
    flags.push_back(absl::StrCat("--sequential-batch ", options.sequential_batch));
  }
  if (options.kernel_lanes > 0) {
    flags.push_back(absl::StrCat("--kernel-lanes ", options.kernel_lanes));
  }
  return absl::StrJoin(flags, " ");
}

Measurement Measure(BenchmarkMesh& mesh, Method method, int threads, RunMode mode,
                    const BenchOptions& options, const RunFunction& run) {
  Measurement measurement;
  measurement.mesh = mesh.spec.name;
  measurement.method = method;
  measurement.threads = threads;
  measurement.mode = mode;
  measurement.target_q_mean = options.target_q_mean;
  measurement.smoothing_options = SmoothingOptionsText(options);
  for (int repeat = 0; repeat < options.repeats; ++repeat) {
    absl::StatusOr<RunMeasurement> result = run(mesh);
    if (!result.ok()) {
      measurement.repeats.clear();
      measurement.error = std::string(result.status().ToString());
      break;
    }
    measurement.repeats.push_back(*std::move(result));
  }
  return measurement;
}

// The engine parameters `getme smooth` would use with the same options.
SmoothingParams ParamsFor(const BenchOptions& options, Method method, int threads) {
  cmdline::SmoothingFlags smooth;
  smooth.method = method;
  smooth.threads = threads;
  smooth.free_boundary = options.free_boundary;
  smooth.literal = options.literal;
  smooth.no_polish = options.no_polish;
  smooth.max_iterations = options.max_iterations;
  smooth.sequential_batch = options.sequential_batch;
  SmoothingParams params = cmdline::ToSmoothingParams(smooth);
  params.kernel_lanes = options.kernel_lanes;  // a benchmark's knob: `getme smooth` has none
  return params;
}

void PrintProgress(const Measurement& measurement) {
  if (measurement.repeats.empty()) {
    absl::FPrintF(stderr, "getme-bench: %s %s t%d %s: failed: %s\n", measurement.mesh,
                  MethodName(measurement.method), measurement.threads,
                  RunModeName(measurement.mode), measurement.error);
    return;
  }
  const RunMeasurement& median = measurement.repeats[MedianRepeat(measurement)];
  absl::FPrintF(stderr, "getme-bench: %s %s t%d %s: q_mean %.4f → %.4f, %.3f s (median of %d)\n",
                measurement.mesh, MethodName(measurement.method), measurement.threads,
                RunModeName(measurement.mode), median.result.before.q_mean,
                median.result.after.q_mean, median.wall_seconds, measurement.repeats.size());
}

absl::Status WriteText(const std::string& path, const std::string& text) {
  std::ofstream file(path);
  file << text << '\n';
  file.close();
  if (!file) return absl::DataLossError(absl::StrCat("cannot write '", path, "'"));
  return absl::OkStatus();
}

absl::Status WriteMesh(const std::string& path, const Mesh& mesh, const std::string& title) {
  return formats::WriteVtkFile(path, formats::GridFromMesh(mesh, title),
                               formats::Encoding::kBinary);
}

// Writes the measurement's JSON and trace (and, with --write-meshes, the mesh as the last repeat
// left it: the smoothed mesh, identical for every repeat).
absl::Status WriteMeasurement(const BenchOptions& options, const Measurement& measurement,
                              const BenchmarkMesh& mesh) {
  if (options.out_dir.empty()) return absl::OkStatus();
  const std::string stem = MeasurementFileStem(measurement);
  const std::filesystem::path dir(options.out_dir);
  std::string trace_file;
  if (!measurement.repeats.empty()) {
    trace_file = stem + ".trace.jsonl";
    if (absl::Status status = WriteTrace((dir / trace_file).string(), measurement, mesh);
        !status.ok()) {
      return status;
    }
    if (options.write_meshes) {
      if (absl::Status status = WriteMesh((dir / (stem + ".vtk")).string(), mesh.mesh, stem);
          !status.ok()) {
        return status;
      }
    }
  }
  return WriteText((dir / (stem + ".json")).string(),
                   MeasurementJson(measurement, mesh, trace_file));
}

#ifdef GETME_BENCH_WITH_SERVICE
std::string DefaultServerBinary() {
  std::error_code error;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", error);
  return (self.parent_path() / "getme-server").string();
}
#endif

int Run(const BenchOptions& options) {
  const auto fail = [](const absl::Status& status) {
    absl::FPrintF(stderr, "getme-bench: %s\n", status.ToString());
    return 1;
  };
  if (!options.out_dir.empty()) {
    std::error_code error;
    std::filesystem::create_directories(options.out_dir, error);
    if (error) {
      return fail(absl::InvalidArgumentError(
          absl::StrCat("cannot create '", options.out_dir, "': ", error.message())));
    }
  }

  std::vector<BenchmarkMesh> meshes;
  for (const MeshSpec& spec : options.meshes) {
    absl::StatusOr<BenchmarkMesh> mesh = LoadBenchmarkMesh(spec);
    if (!mesh.ok()) return fail(mesh.status());
    absl::FPrintF(stderr, "getme-bench: %s: %d nodes, %d elements, loaded in %.2f s\n", spec.name,
                  mesh->mesh.node_count(), mesh->mesh.element_count(), mesh->load_seconds);
    if (options.write_meshes && spec.source == MeshSpec::Source::kGenerator) {
      const std::string path = (std::filesystem::path(options.out_dir) / (spec.name + ".vtk"));
      if (absl::Status status = WriteMesh(path, mesh->mesh, spec.path_or_arguments); !status.ok()) {
        return fail(status);
      }
    }
    meshes.push_back(*std::move(mesh));
  }

#ifdef GETME_BENCH_WITH_SERVICE
  std::unique_ptr<ServerProcess> server;
  std::unique_ptr<ServiceSession> service;
  if (options.service) {
    std::string target = options.server;
    if (target.empty()) {
      const std::string log_path =
          options.out_dir.empty()
              ? absl::StrCat("/tmp/getme-bench-server-", getpid(), ".log")
              : (std::filesystem::path(options.out_dir) / "getme-server.log").string();
      absl::StatusOr<std::unique_ptr<ServerProcess>> started = ServerProcess::Start(
          options.server_binary.empty() ? DefaultServerBinary() : options.server_binary, log_path,
          /*keep_log=*/!options.out_dir.empty());
      if (!started.ok()) return fail(started.status());
      server = *std::move(started);
      target = server->target();
    }
    service = std::make_unique<ServiceSession>(target, server != nullptr ? server->pid() : 0);
  }
#else
  if (options.service) {
    return fail(absl::UnimplementedError(
        "getme-bench was built without the service (GETME_BUILD_SERVICE=OFF); --service and "
        "--server are unavailable"));
  }
#endif

  bool all_ok = true;
  std::vector<Measurement> measurements;
  const auto record = [&](const Measurement& measurement, const BenchmarkMesh& mesh) {
    PrintProgress(measurement);
    all_ok = all_ok && !measurement.repeats.empty();
    if (absl::Status status = WriteMeasurement(options, measurement, mesh); !status.ok()) {
      fail(status);
      all_ok = false;
    }
    measurements.push_back(measurement);
  };
  for (BenchmarkMesh& mesh : meshes) {
    for (const Method method : options.methods) {
      for (const int threads : options.thread_counts) {
        const SmoothingParams params = ParamsFor(options, method, threads);
        record(Measure(mesh, method, threads, RunMode::kInProcess, options,
                       [&](BenchmarkMesh& m) {
                         return RunInProcess(m, params, options.target_q_mean);
                       }),
               mesh);
#ifdef GETME_BENCH_WITH_SERVICE
        if (service != nullptr) {
          record(Measure(mesh, method, threads, RunMode::kService, options,
                         [&](BenchmarkMesh& m) {
                           return service->Run(m, params, options.target_q_mean);
                         }),
                 mesh);
        }
#endif
      }
    }
  }

  std::string summary = MarkdownSummary(measurements, meshes);
  if (const std::string overhead = ServiceOverheadSummary(measurements); !overhead.empty()) {
    absl::StrAppend(&summary, "\n", overhead);
  }
  std::fputs(summary.c_str(), stdout);
  if (!options.out_dir.empty()) {
    if (absl::Status status =
            WriteText((std::filesystem::path(options.out_dir) / "summary.md").string(), summary);
        !status.ok()) {
      return fail(status);
    }
  }
  return all_ok ? 0 : 1;
}

}  // namespace
}  // namespace getme::bench

int main(int argc, char** argv) {
  const std::vector<std::string> args(argv + 1, argv + argc);
  absl::StatusOr<getme::bench::BenchOptions> options = getme::bench::ParseBenchOptions(args);
  if (!options.ok()) {
    absl::FPrintF(stderr, "getme-bench: %s\n\n%s", options.status().message(),
                  getme::bench::kBenchUsage);
    return 2;
  }
  if (options->help) {
    std::fputs(getme::bench::kBenchUsage, stdout);
    return 0;
  }
  return getme::bench::Run(*options);
}
