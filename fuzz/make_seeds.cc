// getme-fuzz-seeds OUT_DIR MESH...: the seed corpus of every fuzz target, written from real meshes
// (the shared Mesquite meshes, tests/data). Each mesh is written in every format and variant the
// readers know, into OUT_DIR/<target>/, so each target starts from files of its own format rather
// than having to discover the syntax; the wire target gets the upload a client sends for it.
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "absl/strings/str_cat.h"
#include "formats/file_io.h"
#include "formats/mesh_file.h"
#include "formats/openfoam/foam_file.h"
#include "formats/openfoam/openfoam_writer.h"
#include "getme/v1/smoother.pb.h"
#include "getme_wire/engine_mesh.h"
#include "google/protobuf/io/coded_stream.h"
#include "google/protobuf/io/zero_copy_stream_impl_lite.h"
#include "google/protobuf/util/json_util.h"
#include "openfoam_fuzz_input.h"
#include "remote/grid_upload.h"
#include "spdlog/spdlog.h"

namespace getme::fuzz {
namespace {

namespace fs = std::filesystem;
using formats::Encoding;
using formats::FileFormat;
using formats::WriteOptions;

struct Variant {
  const char* target;  // the fuzz target's corpus folder
  const char* name;
  FileFormat format;
  WriteOptions options;
};

WriteOptions Options(Encoding encoding, formats::GmshVersion version = formats::GmshVersion::k41,
                     formats::VtuLayout layout = formats::VtuLayout::kAppended,
                     bool compress = false) {
  WriteOptions options;
  options.encoding = encoding;
  options.gmsh_version = version;
  options.vtu_layout = layout;
  options.vtu_compress = compress;
  return options;
}

std::vector<Variant> Variants() {
  using enum Encoding;
  using enum formats::GmshVersion;
  using enum formats::VtuLayout;
  return {
      {"vtk", "ascii.vtk", FileFormat::kVtkLegacy, Options(kAscii)},
      {"vtk", "binary.vtk", FileFormat::kVtkLegacy, Options(kBinary)},
      {"vtu", "ascii.vtu", FileFormat::kVtkXml, Options(kAscii)},
      {"vtu", "inline.vtu", FileFormat::kVtkXml, Options(kBinary, k41, kInline)},
      {"vtu", "appended.vtu", FileFormat::kVtkXml, Options(kBinary, k41, kAppended)},
      {"vtu", "zlib.vtu", FileFormat::kVtkXml, Options(kBinary, k41, kAppended, true)},
      {"gmsh", "ascii22.msh", FileFormat::kGmsh, Options(kAscii, k22)},
      {"gmsh", "binary22.msh", FileFormat::kGmsh, Options(kBinary, k22)},
      {"gmsh", "ascii41.msh", FileFormat::kGmsh, Options(kAscii, k41)},
      {"gmsh", "binary41.msh", FileFormat::kGmsh, Options(kBinary, k41)},
      {"medit", "mesh", FileFormat::kMedit, Options(kAscii)},
      {"su2", "su2", FileFormat::kSu2, Options(kAscii)},
      {"cgns", "cgns", FileFormat::kCgns, Options(kBinary)},
      {"exodus", "exo", FileFormat::kExodus, Options(kBinary)},
  };
}

bool Write(const fs::path& path, const std::string& bytes) {
  fs::create_directories(path.parent_path());
  if (absl::Status status = formats::WriteFileAtomically(path.string(), bytes); !status.ok()) {
    std::fprintf(stderr, "getme-fuzz-seeds: %s\n", status.ToString().c_str());
    return false;
  }
  return true;
}

void AppendDelimited(const google::protobuf::MessageLite& message, std::string& out) {
  google::protobuf::io::StringOutputStream stream(&out);
  google::protobuf::io::CodedOutputStream coded(&stream);
  coded.WriteVarint32(static_cast<std::uint32_t>(message.ByteSizeLong()));
  message.SerializeToCodedStream(&coded);
}

// The request stream a client sends: a header declaring the size, then the coordinates and the
// topology in separate chunks (as the client's chunker splits them).
std::string WireUpload(const v1::Mesh& mesh) {
  std::string out;
  v1::SmoothRequest header;
  v1::MeshSize* size = header.mutable_header()->mutable_expected_size();
  size->set_nodes(mesh.coordinates_size() / 3);
  size->set_tetrahedra(mesh.tetrahedra_size() / 4);
  size->set_hexahedra(mesh.hexahedra_size() / 8);
  size->set_wedges(mesh.wedges_size() / 6);
  size->set_pyramids(mesh.pyramids_size() / 5);
  header.mutable_header()->mutable_result_options()->set_nodes_per_chunk(3);
  AppendDelimited(header, out);
  v1::SmoothRequest coordinates;
  *coordinates.mutable_chunk()->mutable_mesh()->mutable_coordinates() = mesh.coordinates();
  AppendDelimited(coordinates, out);
  v1::SmoothRequest topology;
  *topology.mutable_chunk()->mutable_mesh() = mesh;
  topology.mutable_chunk()->mutable_mesh()->clear_coordinates();
  AppendDelimited(topology, out);
  return out;
}

// The body of HTTP POST /v1/jobs a browser sends for the mesh (docs/http.md).
std::string HttpJobBody(const v1::Mesh& mesh) {
  v1::CreateJobRequest request;
  request.mutable_parameters()->set_simultaneous_max_iterations(5);
  request.mutable_result_options()->set_histogram_bins(10);
  *request.mutable_mesh() = mesh;
  std::string json;
  if (!google::protobuf::util::MessageToJsonString(request, &json).ok()) return {};
  return json;
}

int Run(const fs::path& out, const std::vector<std::string>& inputs) {
  spdlog::set_level(spdlog::level::off);
  int written = 0;
  for (const std::string& input : inputs) {
    absl::StatusOr<formats::MeshDocument> document = formats::ReadMeshDocument(input);
    if (!document.ok()) {
      std::fprintf(stderr, "getme-fuzz-seeds: skipping %s\n", document.status().ToString().c_str());
      continue;
    }
    const std::string stem = fs::path(input).stem().string();
    for (const Variant& variant : Variants()) {
      absl::StatusOr<std::string> bytes =
          formats::SerializeMeshDocument(*document, variant.format, variant.options);
      if (!bytes.ok()) continue;  // e.g. cells a format cannot hold
      const std::string name = absl::StrCat(stem, ".", variant.name);
      // The generic targets read every format.
      for (const char* target : {variant.target, "mesh_file", "engine_mesh"}) {
        written += Write(out / target / name, *bytes) ? 1 : 0;
      }
    }
    // The openfoam target's input: the polyMesh built from the mesh, its files joined
    // (openfoam_fuzz_input.h), ASCII, binary, and binary with gzip-compressed points.
    for (const Encoding encoding : {Encoding::kAscii, Encoding::kBinary}) {
      absl::StatusOr<std::vector<formats::PolyMeshFile>> files =
          formats::SerializeOpenFoam(*document, Options(encoding));
      if (!files.ok()) continue;
      formats::PolyMeshFiles polymesh = PolyMeshFilesOf(*files);
      const bool binary = encoding == Encoding::kBinary;
      written +=
          Write(out / "openfoam" / absl::StrCat(stem, binary ? ".binary" : ".ascii", ".polymesh"),
                JoinPolyMeshInput(polymesh));
      if (!binary) continue;
      if (absl::StatusOr<std::string> gzipped = formats::Gzip(polymesh.points.bytes);
          gzipped.ok()) {
        polymesh.points.bytes = *std::move(gzipped);
        written += Write(out / "openfoam" / absl::StrCat(stem, ".gz.polymesh"),
                         JoinPolyMeshInput(polymesh));
      }
    }
    if (absl::StatusOr<remote::GridWireMesh> wire = remote::ToWireMesh(document->grid); wire.ok()) {
      written += Write(out / "wire_mesh" / absl::StrCat(stem, ".upload"), WireUpload(wire->mesh));
      written += Write(out / "http_job" / absl::StrCat(stem, ".json"), HttpJobBody(wire->mesh));
    }
  }
  std::printf("getme-fuzz-seeds: %d seed files in %s\n", written, out.string().c_str());
  return written > 0 ? 0 : 1;
}

}  // namespace
}  // namespace getme::fuzz

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: getme-fuzz-seeds OUT_DIR MESH...\n");
    return 2;
  }
  return getme::fuzz::Run(argv[1], std::vector<std::string>(argv + 2, argv + argc));
}
