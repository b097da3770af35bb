// (c) one full simultaneous iteration on a hybrid mesh, (d) the gather/scatter floor pass on the
// same mesh and their ratio, and 1 vs 2 threads. Every timed iteration starts from the generated
// mesh (coordinates and qualities restored untimed), so each measures the same, first iteration.

#include <benchmark/benchmark.h>
#include <time.h>

#include <chrono>

#include "bench_meshes.h"
#include "floor_pass.h"
#include "getme/smoothing/element_passes_dispatch.h"
#include "getme/smoothing/simultaneous_iteration.h"
#include "getme/smoothing/smoothing_context.h"

namespace getme::bench {
namespace {

double SecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// CPU time of the calling thread: unlike wall time, it does not grow while other processes hold
// the cores.
double ThreadCpuSeconds() {
  timespec now{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

// A copy of a mesh with everything one simultaneous iteration needs on a given thread count.
class IterationRig {
 public:
  // kernel_lanes: SmoothingParams::kernel_lanes (0 = the widest this machine runs).
  IterationRig(const Mesh& original, int threads, int kernel_lanes = 0)
      : original_(original),
        mesh_(original),
        pool_(threads),
        params_(ParamsFor(threads, kernel_lanes)),
        context_(mesh_, params_, pool_, no_progress_, nullptr),
        initial_quality_(context_.quality),
        iteration_(mesh_) {}

  // Restores the generated mesh (untimed) and returns the seconds of one iteration from it; adds
  // the calling thread's CPU seconds to *cpu_seconds if given.
  double TimeOneIteration(double* cpu_seconds = nullptr) {
    RestoreCoordinates(original_, mesh_);
    context_.quality = initial_quality_;
    const double cpu_start = ThreadCpuSeconds();
    const auto start = std::chrono::steady_clock::now();
    SimultaneousIteration::Outcome outcome = iteration_.Run(context_);
    const double seconds = SecondsSince(start);
    if (cpu_seconds != nullptr) *cpu_seconds += ThreadCpuSeconds() - cpu_start;
    benchmark::DoNotOptimize(outcome);
    return seconds;
  }

  const Mesh& mesh() const { return mesh_; }

 private:
  static SmoothingParams ParamsFor(int threads, int kernel_lanes) {
    SmoothingParams params;
    params.threads = threads;
    params.kernel_lanes = kernel_lanes;
    return params;
  }

  const Mesh& original_;
  Mesh mesh_;
  ThreadPool pool_;
  SmoothingParams params_;
  ProgressCallback no_progress_;
  SmoothingContext context_;
  std::vector<double> initial_quality_;
  SimultaneousIteration iteration_;
};

bool SameCoordinates(const Mesh& a, const Mesh& b) {
  return std::equal(a.x().begin(), a.x().end(), b.x().begin()) &&
         std::equal(a.y().begin(), a.y().end(), b.y().begin()) &&
         std::equal(a.z().begin(), a.z().end(), b.z().begin());
}

// One simultaneous iteration; ns_per_element is the per-element-iteration cost.
void BM_SimultaneousIteration(benchmark::State& state) {
  const Mesh& original = HybridMeshNear(state.range(0));
  IterationRig rig(original, static_cast<int>(state.range(1)));
  double total = 0.0;
  for (auto _ : state) {
    const double seconds = rig.TimeOneIteration();
    state.SetIterationTime(seconds);
    total += seconds;
  }
  const auto elements = static_cast<double>(original.element_count());
  state.counters["elements"] = elements;
  state.counters["ns_per_element"] = 1e9 * total / (elements * state.iterations());
}

// (c) against (d), alternating on the same mesh so both see the same machine load; the element
// passes state.range(1) lanes wide (issue 16, item 2).
void BM_IterationOverFloor(benchmark::State& state) {
  const Mesh& original = HybridMeshNear(state.range(0));
  IterationRig rig(original, 1, static_cast<int>(state.range(1)));
  NodeSums sums;
  double iteration_total = 0.0;
  double floor_total = 0.0;
  for (auto _ : state) {
    const auto start = std::chrono::steady_clock::now();
    GatherScatterPass(original, sums);
    const double floor_seconds = SecondsSince(start);
    benchmark::DoNotOptimize(sums.x.data());
    const double iteration_seconds = rig.TimeOneIteration();
    state.SetIterationTime(iteration_seconds + floor_seconds);
    iteration_total += iteration_seconds;
    floor_total += floor_seconds;
  }
  const double per_element = 1e9 / (static_cast<double>(original.element_count()) *
                                    static_cast<double>(state.iterations()));
  state.counters["elements"] = static_cast<double>(original.element_count());
  state.counters["iteration_ns_per_element"] = iteration_total * per_element;
  state.counters["floor_ns_per_element"] = floor_total * per_element;
  state.counters["iteration_over_floor"] = iteration_total / floor_total;
}

// 1 against 2 threads, alternating; fails if the two give different coordinates. On a machine
// whose cores are busy with other work the wall-time speed-up says little, so the work split is
// reported too: cpu_speedup is the 1-thread CPU time over the CPU time the calling thread spent
// in the 2-thread runs (the pool hands chunks out dynamically, so a thread that gets less of the
// machine also gets fewer chunks: this is the speed-up with both cores free, less the threads'
// memory-bandwidth contention).
void BM_TwoThreadSpeedup(benchmark::State& state) {
  const Mesh& original = HybridMeshNear(state.range(0));
  IterationRig one(original, 1);
  IterationRig two(original, 2);
  double one_total = 0.0;
  double two_total = 0.0;
  double one_cpu = 0.0;
  double two_caller_cpu = 0.0;
  for (auto _ : state) {
    const double one_seconds = one.TimeOneIteration(&one_cpu);
    const double two_seconds = two.TimeOneIteration(&two_caller_cpu);
    state.SetIterationTime(one_seconds + two_seconds);
    one_total += one_seconds;
    two_total += two_seconds;
  }
  if (!SameCoordinates(one.mesh(), two.mesh())) {
    state.SkipWithError("1 and 2 threads gave different coordinates");
    return;
  }
  const double per_element = 1e9 / (static_cast<double>(original.element_count()) *
                                    static_cast<double>(state.iterations()));
  state.counters["elements"] = static_cast<double>(original.element_count());
  state.counters["ns_per_element_1_thread"] = one_total * per_element;
  state.counters["ns_per_element_2_threads"] = two_total * per_element;
  state.counters["speedup"] = one_total / two_total;
  state.counters["cpu_speedup"] = one_cpu / two_caller_cpu;
}

}  // namespace

// Size by size, so each mesh is generated once (bench_meshes.h keeps the last one).
void RegisterSimultaneousIterationBenchmarks() {
  for (std::int64_t size : BenchmarkSizes()) {
    for (int lanes : SupportedLaneWidths()) {
      benchmark::RegisterBenchmark("IterationOverFloor", BM_IterationOverFloor)
          ->Args({size, lanes})
          ->ArgNames({"elements", "lanes"})
          ->UseManualTime()
          ->Unit(benchmark::kMillisecond);
    }
    for (int threads : {1, 2}) {
      benchmark::RegisterBenchmark("SimultaneousIteration", BM_SimultaneousIteration)
          ->Args({size, threads})
          ->ArgNames({"elements", "threads"})
          ->UseManualTime()
          ->Unit(benchmark::kMillisecond);
    }
    if (size >= 100'000) {
      benchmark::RegisterBenchmark("TwoThreadSpeedup", BM_TwoThreadSpeedup)
          ->Args({size})
          ->ArgNames({"elements"})
          ->UseManualTime()
          ->Unit(benchmark::kMillisecond);
    }
  }
}

}  // namespace getme::bench
