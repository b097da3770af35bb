// libFuzzer target: the OpenFOAM polyMesh reader (every file parser — FoamFile header, ASCII and
// binary lists, faceList and faceCompactList, the boundary dictionary, gzip — and the checks
// across files and the cell-shape matching), the writer on what it accepts, and the polyMesh
// builder on the same grid (the path of a mesh converted from another format).
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "absl/strings/str_cat.h"
#include "formats/openfoam/openfoam_reader.h"
#include "formats/openfoam/openfoam_writer.h"
#include "fuzz_check.h"
#include "openfoam_fuzz_input.h"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  getme::fuzz::QuietLogging();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace getme;
  const formats::PolyMeshFiles files =
      fuzz::SplitPolyMeshInput(absl::string_view(reinterpret_cast<const char*>(data), size));
  absl::StatusOr<formats::MeshDocument> document = formats::ParseOpenFoam(files);
  if (!fuzz::Accepted(document.status(), "ParseOpenFoam")) return 0;

  // Written back: only the points file is new, the rest is copied; it reads back the same.
  absl::StatusOr<std::vector<formats::PolyMeshFile>> written =
      formats::SerializeOpenFoam(*document, document->as_read);
  fuzz::CheckOk(written.status(), "SerializeOpenFoam of a parsed polyMesh");
  absl::StatusOr<formats::MeshDocument> again =
      formats::ParseOpenFoam(fuzz::PolyMeshFilesOf(*written));
  fuzz::CheckOk(again.status(), "reading the written polyMesh");
  fuzz::CheckSameGeometry(document->grid, again->grid, "OpenFOAM round trip");
  fuzz::Check(again->openfoam == document->openfoam, "OpenFOAM round trip: extras changed");

  // Built from the grid alone (as from another format): refused only with InvalidArgument (the
  // grid may hold no volume cell the builder takes, e.g. after polyhedra), else it reads back
  // with the same points and volume cells.
  formats::MeshDocument foreign;
  foreign.grid = document->grid;
  absl::StatusOr<std::vector<formats::PolyMeshFile>> built =
      formats::SerializeOpenFoam(foreign, foreign.as_read);
  if (!fuzz::Accepted(built.status(), "building a polyMesh from the grid")) return 0;
  absl::StatusOr<formats::MeshDocument> rebuilt =
      formats::ParseOpenFoam(fuzz::PolyMeshFilesOf(*built));
  fuzz::CheckOk(rebuilt.status(), "reading the built polyMesh");
  // The reader numbers each cell's nodes from its first face, which the builder may order
  // differently: the same cells in the same order, each with the same node set.
  const std::vector<double>& xyz = document->grid.points.reals;
  const std::vector<double>& built_xyz = rebuilt->grid.points.reals;
  fuzz::Check(xyz.size() == built_xyz.size(), "OpenFOAM built from the grid: point count changed");
  for (std::size_t i = 0; i < xyz.size(); ++i) {
    fuzz::Check(xyz[i] == built_xyz[i] || (std::isnan(xyz[i]) && std::isnan(built_xyz[i])),
                absl::StrCat("OpenFOAM built from the grid: coordinate ", i, " changed"));
  }
  const formats::GridCells& cells = document->grid.cells;
  const formats::GridCells& built_cells = rebuilt->grid.cells;
  // The reader puts the volume cells first, polyhedra left out.
  const std::int64_t volume_cells =
      document->openfoam->cell_count - document->openfoam->polyhedron_count;
  fuzz::Check(rebuilt->openfoam->cell_count == volume_cells,
              "OpenFOAM built from the grid: cell count changed");
  for (std::int64_t cell = 0; cell < volume_cells; ++cell) {
    fuzz::Check(
        built_cells.types[cell] == cells.types[cell] &&
            std::is_permutation(cells.nodes(cell), cells.nodes(cell) + cells.node_count(cell),
                                built_cells.nodes(cell)),
        absl::StrCat("OpenFOAM built from the grid: cell ", cell, " changed"));
  }
  return 0;
}
