// getme_micro_bench: Google Benchmark's main plus --max_elements=N, the largest mesh of the
// size-dependent benchmarks (10k, 100k, ... up to N; default 1M).

#include <benchmark/benchmark.h>

#include <cstdlib>
#include <cstring>
#include <vector>

#include "bench_meshes.h"

namespace getme::bench {
void RegisterSimultaneousIterationBenchmarks();
void RegisterEngineMemoryBenchmarks();
void RegisterFileIoBenchmarks();
}  // namespace getme::bench

int main(int argc, char** argv) {
  constexpr const char* kFlag = "--max_elements=";
  std::vector<char*> remaining;
  for (int i = 0; i < argc; ++i) {
    if (std::strncmp(argv[i], kFlag, std::strlen(kFlag)) == 0) {
      getme::bench::SetMaxBenchmarkElements(std::atoll(argv[i] + std::strlen(kFlag)));
    } else {
      remaining.push_back(argv[i]);
    }
  }
  int remaining_count = static_cast<int>(remaining.size());
  getme::bench::RegisterSimultaneousIterationBenchmarks();
  getme::bench::RegisterEngineMemoryBenchmarks();
  getme::bench::RegisterFileIoBenchmarks();
  benchmark::Initialize(&remaining_count, remaining.data());
  if (benchmark::ReportUnrecognizedArguments(remaining_count, remaining.data())) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
