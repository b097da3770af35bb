// Readers and writers of large mesh files (issue 16, item 4: "reading and writing a 10M-element
// mesh must not dominate the run"): MB/s of each binary format's writer and reader, and of ASCII
// VTK legacy (the form of the shared Mesquite meshes), on the distorted hybrid block of the other
// benchmarks, at every size of BenchmarkSizes(). The writer is SerializeMeshDocument and the
// atomic file write; the reader is the file read and ParseMeshDocument, which is what
// `getme smooth` does with its input. The file goes to the temporary directory and is removed
// afterwards; bytes_per_second counts the file's bytes. MeshBuild is the step after reading:
// GridToMesh, which checks the connectivity and finds the boundary.

#include <benchmark/benchmark.h>

#include <cstdio>
#include <filesystem>
#include <string>

#include "bench_meshes.h"
#include "formats/file_io.h"
#include "formats/grid_mesh.h"
#include "formats/mesh_file.h"

namespace getme::bench {
namespace {

struct FormatCase {
  const char* name;
  const char* extension;
  formats::FileFormat format;
  formats::WriteOptions options;
  // Read and written by path (WriteMeshDocument / ReadMeshDocument), as `getme` does: the CGNS
  // library opens files by name, and going through bytes would add a temporary file.
  bool by_path = false;
};

const FormatCase kFormats[] = {
    {"vtu",
     ".vtu",
     formats::FileFormat::kVtkXml,
     {formats::Encoding::kBinary, formats::GmshVersion::k41, formats::VtuLayout::kAppended, false}},
    {"msh41",
     ".msh",
     formats::FileFormat::kGmsh,
     {formats::Encoding::kBinary, formats::GmshVersion::k41, formats::VtuLayout::kAppended, false}},
    {"vtk",
     ".vtk",
     formats::FileFormat::kVtkLegacy,
     {formats::Encoding::kBinary, formats::GmshVersion::k41, formats::VtuLayout::kAppended, false}},
    {"vtk_ascii",
     ".vtk",
     formats::FileFormat::kVtkLegacy,
     {formats::Encoding::kAscii, formats::GmshVersion::k41, formats::VtuLayout::kAppended, false}},
    {"cgns",
     ".cgns",
     formats::FileFormat::kCgns,
     {formats::Encoding::kBinary, formats::GmshVersion::k41, formats::VtuLayout::kAppended, false},
     true},
};

std::int64_t FileBytes(const std::string& path) {
  std::error_code error;
  const auto size = std::filesystem::file_size(path, error);
  return error ? 0 : static_cast<std::int64_t>(size);
}

formats::MeshDocument DocumentOf(const Mesh& mesh, const FormatCase& format) {
  formats::MeshDocument document;
  document.format = format.format;
  document.as_read = format.options;
  document.grid = formats::GridFromMesh(mesh, "hybrid block");
  return document;
}

std::string TempFile(const FormatCase& format) {
  return (std::filesystem::temp_directory_path() /
          (std::string("getme_file_io_bench") + format.extension))
      .string();
}

void BM_Write(benchmark::State& state, const FormatCase* format) {
  const formats::MeshDocument document = DocumentOf(HybridMeshNear(state.range(0)), *format);
  const std::string path = TempFile(*format);
  std::int64_t bytes = 0;
  for (auto _ : state) {
    if (format->by_path) {
      if (!formats::WriteMeshDocument(path, document, format->format, format->options).ok()) {
        state.SkipWithError("write failed");
        break;
      }
      bytes = FileBytes(path);
      continue;
    }
    absl::StatusOr<std::string> serialized =
        formats::SerializeMeshDocument(document, format->format, format->options);
    if (!serialized.ok() || !formats::WriteFileAtomically(path, *serialized).ok()) {
      state.SkipWithError("write failed");
      break;
    }
    bytes = static_cast<std::int64_t>(serialized->size());
  }
  std::filesystem::remove(path);
  state.SetBytesProcessed(bytes * state.iterations());
  state.counters["elements"] = static_cast<double>(state.range(0));
  state.counters["file_MB"] = static_cast<double>(bytes) / 1e6;
}

void BM_Read(benchmark::State& state, const FormatCase* format) {
  const std::string path = TempFile(*format);
  {
    const formats::MeshDocument document = DocumentOf(HybridMeshNear(state.range(0)), *format);
    absl::StatusOr<std::string> serialized =
        formats::SerializeMeshDocument(document, format->format, format->options);
    if (!serialized.ok() || !formats::WriteFileAtomically(path, *serialized).ok()) {
      state.SkipWithError("could not write the file to read");
      return;
    }
  }
  std::int64_t bytes = 0;
  for (auto _ : state) {
    if (format->by_path) {
      absl::StatusOr<formats::MeshDocument> document =
          formats::ReadMeshDocument(path, format->format);
      if (!document.ok()) {
        state.SkipWithError("read failed");
        break;
      }
      bytes = FileBytes(path);
      benchmark::DoNotOptimize(document->grid.point_count());
      continue;
    }
    absl::StatusOr<std::string> file = formats::ReadFileBytes(path);
    absl::StatusOr<formats::MeshDocument> document =
        file.ok() ? formats::ParseMeshDocument(*file, format->format)
                  : absl::StatusOr<formats::MeshDocument>(file.status());
    if (!document.ok()) {
      state.SkipWithError("read failed");
      break;
    }
    bytes = static_cast<std::int64_t>(file->size());
    benchmark::DoNotOptimize(document->grid.point_count());
  }
  std::filesystem::remove(path);
  state.SetBytesProcessed(bytes * state.iterations());
  state.counters["elements"] = static_cast<double>(state.range(0));
  state.counters["file_MB"] = static_cast<double>(bytes) / 1e6;
}

void BM_MeshBuild(benchmark::State& state) {
  const formats::UnstructuredGrid grid =
      formats::GridFromMesh(HybridMeshNear(state.range(0)), "hybrid block");
  for (auto _ : state) {
    absl::StatusOr<formats::GridMesh> built = formats::GridToMesh(grid);
    if (!built.ok()) {
      state.SkipWithError("build failed");
      break;
    }
    benchmark::DoNotOptimize(built->mesh.element_count());
  }
  state.SetItemsProcessed(state.range(0) * state.iterations());
  state.counters["elements"] = static_cast<double>(state.range(0));
}

}  // namespace

void RegisterFileIoBenchmarks() {
  for (const std::int64_t size : BenchmarkSizes()) {
    for (const FormatCase& format : kFormats) {
      benchmark::RegisterBenchmark((std::string("FileWrite/") + format.name).c_str(), BM_Write,
                                   &format)
          ->Arg(size)
          ->Unit(benchmark::kMillisecond)
          ->UseRealTime();
      benchmark::RegisterBenchmark((std::string("FileRead/") + format.name).c_str(), BM_Read,
                                   &format)
          ->Arg(size)
          ->Unit(benchmark::kMillisecond)
          ->UseRealTime();
    }
    benchmark::RegisterBenchmark("MeshBuild", BM_MeshBuild)
        ->Arg(size)
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime();
  }
}

}  // namespace getme::bench
