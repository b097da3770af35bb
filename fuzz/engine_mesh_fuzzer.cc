// libFuzzer target: what `getme smooth` does with a file before and after the engine runs —
// sniff, read, convert to the engine mesh (GridToMesh) with the fixed nodes --fix-surfaces selects,
// write the quality arrays back (UpdateGridFromMesh), write the file and read it again — and the
// engine-mesh → file conversion (GridFromMesh). The engine itself is not run.
#include <algorithm>
#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>

#include "absl/strings/str_cat.h"
#include "formats/grid_mesh.h"
#include "formats/mesh_file.h"
#include "formats/vtk_reader.h"
#include "formats/vtk_writer.h"
#include "fuzz_check.h"
#include "getme/elements/node_orders.h"

namespace getme::fuzz {
namespace {

bool SameBits(double a, double b) {
  return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

// The engine mesh holds exactly the file's points and volume cells, in the paper's node order.
void CheckMeshMatchesFile(const formats::GridMesh& converted,
                          const formats::UnstructuredGrid& file) {
  const Mesh& mesh = converted.mesh;
  Check(mesh.node_count() == file.point_count(), "GridToMesh: node count is not the point count");
  for (std::int64_t node = 0; node < mesh.node_count(); ++node) {
    Check(SameBits(mesh.x()[node], file.points.AsDouble(3 * node)) &&
              SameBits(mesh.y()[node], file.points.AsDouble(3 * node + 1)) &&
              SameBits(mesh.z()[node], file.points.AsDouble(3 * node + 2)),
          absl::StrCat("GridToMesh: node ", node, " moved"));
  }
  Check(static_cast<std::int64_t>(converted.cell_elements.size()) == file.cells.size(),
        "GridToMesh: the cell map does not cover the cells");
  Check(static_cast<std::int64_t>(converted.element_cells.size()) == mesh.element_count(),
        "GridToMesh: the element map does not cover the elements");
  for (ElementId element = 0; element < mesh.element_count(); ++element) {
    const std::int64_t cell = converted.element_cells[element];
    Check(cell >= 0 && cell < file.cells.size() && converted.cell_elements[cell] == element,
          absl::StrCat("GridToMesh: element ", element, " and its cell do not map to each other"));
    const std::span<const NodeId> nodes = mesh.element_nodes(element);
    Check(static_cast<std::int64_t>(nodes.size()) == file.cells.node_count(cell),
          absl::StrCat("GridToMesh: element ", element, " has another node count than its cell"));
    const ElementType type = mesh.type(element);
    for (std::size_t k = 0; k < nodes.size(); ++k) {
      Check(nodes[k] == file.cells.nodes(cell)[VtkToPaperPosition(type, static_cast<int>(k))],
            absl::StrCat("GridToMesh: element ", element, " node ", k, " is not its cell's"));
    }
  }
}

// Elements, nodes and fixed flags equal, coordinates bit-identical.
void CheckSameMesh(const Mesh& expected, const Mesh& actual, absl::string_view what) {
  Check(expected.node_count() == actual.node_count() &&
            expected.element_count() == actual.element_count(),
        absl::StrCat(what, ": node or element count changed"));
  for (std::int64_t node = 0; node < expected.node_count(); ++node) {
    Check(SameBits(expected.x()[node], actual.x()[node]) &&
              SameBits(expected.y()[node], actual.y()[node]) &&
              SameBits(expected.z()[node], actual.z()[node]),
          absl::StrCat(what, ": node ", node, " moved"));
    Check(
        expected.is_fixed(static_cast<NodeId>(node)) == actual.is_fixed(static_cast<NodeId>(node)),
        absl::StrCat(what, ": node ", node, " changed its fixed flag"));
  }
  for (ElementId element = 0; element < expected.element_count(); ++element) {
    const std::span<const NodeId> a = expected.element_nodes(element);
    const std::span<const NodeId> b = actual.element_nodes(element);
    Check(expected.type(element) == actual.type(element) &&
              std::equal(a.begin(), a.end(), b.begin(), b.end()),
          absl::StrCat(what, ": element ", element, " changed"));
  }
}

void CheckQualityArrays(const formats::UnstructuredGrid& file) {
  for (const char* name : {"mean_ratio", "warpage", "valid"}) {
    const formats::DataArray* array = formats::FindArray(file.cell_data, name);
    Check(array != nullptr && array->tuple_count() == file.cells.size(),
          absl::StrCat("UpdateGridFromMesh: no '", name, "' value per cell"));
  }
}

}  // namespace
}  // namespace getme::fuzz

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  getme::fuzz::QuietLogging();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace getme;
  using fuzz::Accepted;
  using fuzz::Check;
  using fuzz::CheckOk;
  const absl::string_view bytes(reinterpret_cast<const char*>(data), size);
  const std::optional<formats::FileFormat> format = formats::SniffFormat(bytes);
  if (!format.has_value()) return 0;
  absl::StatusOr<formats::MeshDocument> document = formats::ParseMeshDocument(bytes, *format);
  if (!document.ok()) return 0;  // the reader targets check its errors
  absl::StatusOr<formats::GridMesh> converted = formats::GridToMesh(document->grid);
  if (!Accepted(converted.status(), "GridToMesh")) return 0;
  fuzz::CheckMeshMatchesFile(*converted, document->grid);
  Mesh& mesh = converted->mesh;

  // --fix-surfaces: the nodes of every cell of dimension 0-2.
  absl::StatusOr<std::vector<std::uint8_t>> fixed =
      formats::SelectFixedNodes(*document, {}, /*surface_cells=*/true);
  CheckOk(fixed.status(), "SelectFixedNodes without groups");
  Check(static_cast<std::int64_t>(fixed->size()) == mesh.node_count(),
        "SelectFixedNodes: not one flag per node");
  for (std::size_t node = 0; node < fixed->size(); ++node) {
    if ((*fixed)[node] != 0) mesh.set_fixed(static_cast<NodeId>(node), true);
  }

  // A mesh that came from no file (the service's results) written as VTK and read back.
  absl::StatusOr<std::string> vtk =
      formats::SerializeVtk(formats::GridFromMesh(mesh, "fuzz"), formats::Encoding::kBinary);
  CheckOk(vtk.status(), "SerializeVtk of GridFromMesh");
  absl::StatusOr<formats::UnstructuredGrid> vtk_again = formats::ParseVtk(*vtk);
  CheckOk(vtk_again.status(), "ParseVtk of GridFromMesh's file");
  absl::StatusOr<formats::GridMesh> from_mesh_again = formats::GridToMesh(*vtk_again);
  CheckOk(from_mesh_again.status(), "GridToMesh of GridFromMesh's file");
  fuzz::CheckSameMesh(mesh, from_mesh_again->mesh, "GridFromMesh → VTK → GridToMesh");

  // The quality arrays written into the document, the document written in its own format.
  CheckOk(formats::UpdateGridFromMesh(mesh, converted->cell_elements, document->grid),
          "UpdateGridFromMesh of GridToMesh's mesh");
  fuzz::CheckQualityArrays(document->grid);
  absl::StatusOr<std::string> written =
      formats::SerializeMeshDocument(*document, document->format, document->as_read);
  if (!written.ok() && document->as_read.encoding == formats::Encoding::kBinary) {
    // A binary variant may hold less than the ASCII one: MSH's binary $ElementData has 32-bit
    // element tags, so the new quality arrays of elements tagged beyond 2^31 are refused there
    // ("… write ASCII"). The ASCII variant must then hold it.
    Accepted(written.status(), "binary write");
    formats::WriteOptions ascii = document->as_read;
    ascii.encoding = formats::Encoding::kAscii;
    written = formats::SerializeMeshDocument(*document, document->format, ascii);
  }
  CheckOk(written.status(),
          absl::StrCat("writing the updated ", fuzz::FormatName(document->format), " document"));
  absl::StatusOr<formats::MeshDocument> reread = formats::ParseMeshDocument(*written, *format);
  CheckOk(reread.status(), "reading the written document");
  absl::StatusOr<formats::GridMesh> reconverted = formats::GridToMesh(reread->grid);
  CheckOk(reconverted.status(), "GridToMesh of the written document");
  Check(reconverted->mesh.node_count() == mesh.node_count() &&
            reconverted->mesh.element_count() == mesh.element_count(),
        "the written document has another mesh");
  for (std::int64_t node = 0; node < mesh.node_count(); ++node) {
    Check(fuzz::SameBits(mesh.x()[node], reconverted->mesh.x()[node]) &&
              fuzz::SameBits(mesh.y()[node], reconverted->mesh.y()[node]) &&
              fuzz::SameBits(mesh.z()[node], reconverted->mesh.z()[node]),
          absl::StrCat("written document: node ", node, " moved"));
  }
  return 0;
}
