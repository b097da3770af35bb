// Engine memory per element (issue 5 aims below 300 bytes): the resident memory a generated
// hybrid mesh adds, and the peak a full GETMe run (simultaneous, then sequential) adds on top,
// from the kernel's counters (VmRSS, and VmHWM reset through /proc/self/clear_refs). The mesh's
// arrays are also summed by size as a cross-check that names where the bytes go.

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

#include "bench_meshes.h"
#include "getme/meshgen/distorted_hex_block.h"
#include "getme/smoothing/smoother.h"

namespace getme::bench {
namespace {

// A field of /proc/self/status (VmRSS, VmHWM) in bytes; -1 if unavailable.
double ProcStatusBytes(const std::string& field) {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line)) {
    if (line.rfind(field + ":", 0) == 0) return 1024.0 * std::stod(line.substr(field.size() + 1));
  }
  return -1.0;
}

// Lets VmHWM start again from the current resident size.
bool ResetPeakResident() {
  std::ofstream clear_refs("/proc/self/clear_refs");
  clear_refs << "5";
  return static_cast<bool>(clear_refs.flush());
}

// The mesh's arrays by their sizes (capacity slack not included). Mesh::element_neighbours is
// left out: the engine never builds that table (ElementNeighbourFinder).
double MeshArrayBytes(const Mesh& mesh) {
  const auto nodes = static_cast<double>(mesh.node_count());
  const auto elements = static_cast<double>(mesh.element_count());
  const auto corners = static_cast<double>(mesh.corner_count());
  const double coordinates_and_flags = nodes * (3 * sizeof(double) + 2);
  // Type, block index, block entry and canonical order entry.
  const double element_arrays = elements * (sizeof(ElementType) + 3 * sizeof(std::int32_t));
  const double connectivity = corners * sizeof(NodeId);
  const double node_rows = (nodes + 1) * 8 + corners * 4;  // node→element
  return coordinates_and_flags + element_arrays + connectivity + node_rows;
}

// kind 0: the hybrid mesh of the other benchmarks (mostly tetrahedra, 4.1 corners and 0.24 nodes
// per element); kind 1: distorted hexahedra (8 corners and 1 node per element), the most memory
// per element: the largest connectivity and node→element rows, and a node's sums per element.
Mesh GenerateMesh(std::int64_t elements, int kind) {
  if (kind == 0) return GenerateHybridMeshNear(elements);
  const int n = static_cast<int>(std::lround(std::cbrt(static_cast<double>(elements))));
  auto mesh = meshgen::DistortedHexBlock(n, n, n, 0.3, 5);
  if (!mesh.ok()) std::abort();
  return *std::move(mesh);
}

void BM_EngineMemory(benchmark::State& state) {
  ReleaseHybridMesh();
  for (auto _ : state) {
    const double before = ProcStatusBytes("VmRSS");
    Mesh mesh = GenerateMesh(state.range(0), static_cast<int>(state.range(1)));
    const double with_mesh = ProcStatusBytes("VmRSS");
    if (!ResetPeakResident()) {
      state.SkipWithError("cannot reset VmHWM through /proc/self/clear_refs");
      return;
    }
    SmoothingParams params;
    params.threads = 1;
    params.simultaneous_max_iterations = 3;  // the buffers are the same for any iteration count
    params.sequential_max_iterations = 10'000;
    auto result = Smooth(mesh, params);
    if (!result.ok()) {
      state.SkipWithError(result.status().ToString().c_str());
      return;
    }
    const double peak = ProcStatusBytes("VmHWM");
    const auto elements = static_cast<double>(mesh.element_count());
    state.counters["elements"] = elements;
    state.counters["nodes_per_element"] = static_cast<double>(mesh.node_count()) / elements;
    state.counters["mesh_rss_bytes_per_element"] = (with_mesh - before) / elements;
    state.counters["mesh_array_bytes_per_element"] = MeshArrayBytes(mesh) / elements;
    state.counters["smoothing_peak_bytes_per_element"] = (peak - with_mesh) / elements;
    state.counters["engine_peak_bytes_per_element"] = (peak - before) / elements;
  }
}

}  // namespace

void RegisterEngineMemoryBenchmarks() {
  for (std::int64_t size : BenchmarkSizes()) {
    if (size < 1'000'000) continue;  // smaller meshes: allocator noise outweighs the arrays
    for (int kind : {0, 1}) {
      benchmark::RegisterBenchmark(kind == 0 ? "EngineMemory/hybrid" : "EngineMemory/hex",
                                   BM_EngineMemory)
          ->Args({size, kind})
          ->ArgNames({"elements", "kind"})
          ->Iterations(1)
          ->Unit(benchmark::kMillisecond);
    }
  }
}

}  // namespace getme::bench
