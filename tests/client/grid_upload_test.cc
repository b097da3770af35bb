// A file's grid as a wire upload and the smoothed coordinates back, checked against hand-written
// expectations (VTK wedge order, wire element grouping).

#include "remote/grid_upload.h"

#include <gtest/gtest.h>

#include <array>
#include <vector>

#include "formats/unstructured_grid.h"

namespace getme::remote {
namespace {

std::vector<std::uint32_t> Values(const google::protobuf::RepeatedField<std::uint32_t>& field) {
  return {field.begin(), field.end()};
}

// Points 0..7 of a unit cube; cells interleave types and include a passthrough quad.
formats::UnstructuredGrid MixedFile() {
  formats::UnstructuredGrid file;
  file.points.components = 3;
  const std::array<std::array<double, 3>, 8> points = {
      {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}}};
  for (const auto& point : points)
    file.points.reals.insert(file.points.reals.end(), point.begin(), point.end());
  file.cells.Add(13, {0, 1, 2, 4, 5, 6});        // wedge, cell 0
  file.cells.Add(9, {0, 1, 2, 3});               // quad (passthrough), cell 1
  file.cells.Add(10, {0, 1, 3, 4});              // tetra, cell 2
  file.cells.Add(14, {0, 1, 2, 3, 7});           // pyramid, cell 3
  file.cells.Add(12, {0, 1, 2, 3, 4, 5, 6, 7});  // hexahedron, cell 4
  file.cells.Add(10, {1, 2, 3, 6});              // tetra, cell 5
  formats::VtkAttribute fixed{formats::VtkAttributeKind::kScalars, "fixed", "default", {}};
  formats::DataArray flags;
  flags.name = "fixed";
  flags.type = formats::VtkDataType::kInt;
  flags.integers = {0, 1, 0, 0, 0, 0, 1, 0};
  fixed.arrays.push_back(flags);
  file.point_data.push_back(fixed);
  return file;
}

TEST(ToWireMesh, GroupsCellsByTypeInVtkOrderAndSkipsPassthrough) {
  const absl::StatusOr<GridWireMesh> wire = ToWireMesh(MixedFile());
  ASSERT_TRUE(wire.ok()) << wire.status();
  EXPECT_EQ(wire->mesh.coordinates_size(), 24);
  EXPECT_EQ(wire->mesh.coordinates(20), 1.0);  // y of point 6
  EXPECT_EQ(Values(wire->mesh.tetrahedra()), (std::vector<std::uint32_t>{0, 1, 3, 4, 1, 2, 3, 6}));
  EXPECT_EQ(Values(wire->mesh.hexahedra()), (std::vector<std::uint32_t>{0, 1, 2, 3, 4, 5, 6, 7}));
  // The wire carries VTK's wedge order; the server mirrors it.
  EXPECT_EQ(Values(wire->mesh.wedges()), (std::vector<std::uint32_t>{0, 1, 2, 4, 5, 6}));
  EXPECT_EQ(Values(wire->mesh.pyramids()), (std::vector<std::uint32_t>{0, 1, 2, 3, 7}));
  EXPECT_EQ(Values(wire->mesh.fixed_nodes()), (std::vector<std::uint32_t>{1, 6}));
  // Wire numbering: tets (cells 2, 5), hex (4), wedge (0), pyramid (3).
  EXPECT_EQ(wire->element_cells, (std::vector<std::int64_t>{2, 5, 4, 0, 3}));
}

TEST(ToWireMesh, RefusesUnsupportedCellNamingIt) {
  formats::UnstructuredGrid file = MixedFile();
  file.cells.Add(11, {0, 1, 2, 3, 4, 5, 6, 7});  // voxel
  const absl::StatusOr<GridWireMesh> wire = ToWireMesh(file);
  ASSERT_EQ(wire.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_NE(wire.status().message().find("cell 6 has VTK type 11"), std::string::npos)
      << wire.status();
}

TEST(ApplyCoordinates, WritesDoublesAndChecksTheCount) {
  formats::UnstructuredGrid file = MixedFile();
  std::vector<double> moved(24);
  for (int i = 0; i < 24; ++i) moved[i] = 0.1 * i;
  ASSERT_TRUE(ApplyCoordinates(moved, file).ok());
  EXPECT_EQ(file.points.reals, moved);
  moved.pop_back();
  EXPECT_EQ(ApplyCoordinates(moved, file).code(), absl::StatusCode::kInvalidArgument);
}

}  // namespace
}  // namespace getme::remote
