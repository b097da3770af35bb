#include "cgns_test_files.h"

#include <cgnslib.h>
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "nlohmann/json.hpp"

namespace getme::formats::testing {

std::string FixturePath(const std::string& name) { return std::string(CGNS_FIXTURES) + "/" + name; }

ExpectedMesh ReadExpected(const std::string& path) {
  std::ifstream in(path);
  EXPECT_TRUE(in.good()) << "missing " << path;
  ExpectedMesh expected;
  if (!in.good()) return expected;
  const nlohmann::json json = nlohmann::json::parse(in);
  for (const auto& point : json["points"]) {
    for (const auto& value : point) expected.points.push_back(value.get<double>());
  }
  for (const auto& cell : json["cells"]) {
    expected.cells.Add(cell[0].get<int>(), cell[1].get<std::vector<std::int64_t>>());
  }
  for (const auto& bc : json["bcs"]) {
    expected.bcs.push_back({bc["name"].get<std::string>(), bc["type"].get<std::string>(),
                            bc["cells"].get<std::vector<std::int64_t>>()});
  }
  return expected;
}

namespace {

#define CHECK_CG(call) EXPECT_EQ((call), CG_OK) << #call << ": " << cg_get_error()

constexpr double kS3 = 1.7320508075688772;

}  // namespace

std::vector<double> LibraryFilePoints() {
  // A regular tetrahedron 0-3 and a regular prism 4-9 beside it (bottom counter-clockwise seen
  // from the top: SIDS PENTA_6 order).
  return {0, 0,   0,       1, 0, 0, 0.5, kS3 / 2, 0, 0.5, kS3 / 6, 0.816496580927726, 3, 0, 0, 4, 0,
          0, 3.5, kS3 / 2, 0, 3, 0, 1,   4,       0, 1,   3.5,     kS3 / 2,           1};
}

GridCells LibraryFileCells() {
  GridCells cells;
  cells.Add(10, {0, 1, 2, 3});
  cells.Add(13, {4, 6, 5, 7, 9, 8});  // VTK's wedge: the PENTA_6 mirrored
  cells.Add(5, {0, 2, 1});
  return cells;
}

std::string WriteLibraryFile(const LibraryFileOptions& options) {
  CHECK_CG(cg_set_file_type(options.file_type));
  int file = 0;
  CHECK_CG(cg_open(options.path.c_str(), CG_MODE_WRITE, &file));
  int base = 0;
  CHECK_CG(cg_base_write(file, "Base", options.cell_dimension, 3, &base));
  const std::vector<double> points = LibraryFilePoints();
  for (int z = 1; z <= options.zones; ++z) {
    const std::string zone_name = "Zone" + std::to_string(z);
    int zone = 0;
    if (options.structured) {
      cgsize_t size[9] = {2, 2, 2, 1, 1, 1, 0, 0, 0};
      CHECK_CG(cg_zone_write(file, base, zone_name.c_str(), size, Structured, &zone));
      continue;
    }
    cgsize_t size[3] = {10, 2, 0};
    CHECK_CG(cg_zone_write(file, base, zone_name.c_str(), size, Unstructured, &zone));
    static constexpr const char* kAxes[3] = {"CoordinateX", "CoordinateY", "CoordinateZ"};
    for (int axis = 0; axis < 3; ++axis) {
      std::vector<double> values;
      for (std::size_t i = axis; i < points.size(); i += 3) values.push_back(points[i]);
      int index = 0;
      CHECK_CG(cg_coord_write(file, base, zone, RealDouble, kAxes[axis], values.data(), &index));
    }
    int section = 0;
    if (options.element_type == MIXED) {
      std::vector<cgsize_t> prism = {5, 6, 7, 8, 9, 10};
      if (options.prism_in_vtk_order) prism = {5, 7, 6, 8, 10, 9};
      std::vector<cgsize_t> connectivity = {TETRA_4, 1, 2, 3, 4, PENTA_6};
      connectivity.insert(connectivity.end(), prism.begin(), prism.end());
      const cgsize_t offsets[3] = {0, 5, 12};
      CHECK_CG(cg_poly_section_write(file, base, zone, "Cells", MIXED, 1, 2, 0, connectivity.data(),
                                     offsets, &section));
    } else {
      // Two elements of the given type: as many nodes as it needs, from 1 up (only the
      // refusal of the type is tested).
      int nodes = 0;
      cg_npe(static_cast<ElementType_t>(options.element_type), &nodes);
      std::vector<cgsize_t> connectivity;
      for (int e = 0; e < 2; ++e) {
        for (int k = 0; k < nodes; ++k) connectivity.push_back(k % 10 + 1);
      }
      CHECK_CG(cg_section_write(file, base, zone, "Cells",
                                static_cast<ElementType_t>(options.element_type), 1, 2, 0,
                                connectivity.data(), &section));
    }
    const cgsize_t triangle[3] = {1, 3, 2};
    CHECK_CG(cg_section_write(file, base, zone, "Faces", TRI_3, 3, 3, 0, triangle, &section));
    if (options.with_family_and_vertex_bc) {
      if (z == 1) {  // families belong to the base
        int family = 0;
        CHECK_CG(cg_family_write(file, base, "Walls", &family));
        int family_bc = 0;
        CHECK_CG(cg_fambc_write(file, base, family, "FamBC", BCWall, &family_bc));
      }
      int bc = 0;
      const cgsize_t faces[1] = {options.bc_element};
      CHECK_CG(cg_boco_write(file, base, zone, "inlet", FamilySpecified, PointList, 1, faces, &bc));
      CHECK_CG(cg_boco_gridlocation_write(file, base, zone, bc, FaceCenter));
      CHECK_CG(cg_goto(file, base, "Zone_t", zone, "ZoneBC_t", 1, "BC_t", bc, "end"));
      CHECK_CG(cg_famname_write("Walls"));
      const cgsize_t vertices[2] = {1, 2};
      CHECK_CG(cg_boco_write(file, base, zone, "pins", BCWall, PointList, 2, vertices, &bc));
      CHECK_CG(cg_boco_gridlocation_write(file, base, zone, bc, Vertex));
    }
  }
  CHECK_CG(cg_close(file));
  return options.path;
}

}  // namespace getme::formats::testing
