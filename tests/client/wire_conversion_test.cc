// Conversions between files, engine types and wire messages, checked against hand-written
// expectations (VTK wedge order, wire element grouping, parameter defaults).

#include "remote/wire_conversion.h"

#include <gtest/gtest.h>

#include <array>
#include <vector>

#include "formats/vtk_file.h"
#include "remote/wire_mesh.h"

namespace getme::remote {
namespace {

std::vector<std::uint32_t> Values(const google::protobuf::RepeatedField<std::uint32_t>& field) {
  return {field.begin(), field.end()};
}

// Points 0..7 of a unit cube; cells interleave types and include a passthrough quad.
formats::VtkFile MixedFile() {
  formats::VtkFile file;
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
  formats::VtkDataArray flags;
  flags.name = "fixed";
  flags.type = formats::VtkDataType::kInt;
  flags.integers = {0, 1, 0, 0, 0, 0, 1, 0};
  fixed.arrays.push_back(flags);
  file.point_data.push_back(fixed);
  return file;
}

TEST(ToWireMesh, GroupsCellsByTypeInVtkOrderAndSkipsPassthrough) {
  const absl::StatusOr<VtkWireMesh> wire = ToWireMesh(MixedFile());
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
  formats::VtkFile file = MixedFile();
  file.cells.Add(11, {0, 1, 2, 3, 4, 5, 6, 7});  // voxel
  const absl::StatusOr<VtkWireMesh> wire = ToWireMesh(file);
  ASSERT_EQ(wire.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_NE(wire.status().message().find("cell 6 has VTK type 11"), std::string::npos)
      << wire.status();
}

TEST(ToWireMesh, EngineMeshPrismsGoBackToVtkWedgeOrder) {
  MeshBuilder builder;
  for (int i = 0; i < 6; ++i) builder.AddNode(i % 3 == 1 ? 1 : 0, i % 3 == 2 ? 1 : 0, i / 3);
  // VTK wedge (0, 1, 2, 3, 4, 5) is paper prism (0, 2, 1, 3, 5, 4).
  const std::array<std::int64_t, 6> paper = {0, 2, 1, 3, 5, 4};
  builder.AddElement(ElementType::kPrism, paper);
  builder.SetFixed(4);
  absl::StatusOr<Mesh> mesh = std::move(builder).Build();
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  const v1::Mesh wire = ToWireMesh(*mesh);
  EXPECT_EQ(Values(wire.wedges()), (std::vector<std::uint32_t>{0, 1, 2, 3, 4, 5}));
  EXPECT_EQ(Values(wire.fixed_nodes()), (std::vector<std::uint32_t>{4}));
  EXPECT_EQ(wire.coordinates_size(), 18);
}

TEST(ApplyCoordinates, WritesDoublesAndChecksTheCount) {
  formats::VtkFile file = MixedFile();
  std::vector<double> moved(24);
  for (int i = 0; i < 24; ++i) moved[i] = 0.1 * i;
  ASSERT_TRUE(ApplyCoordinates(moved, file).ok());
  EXPECT_EQ(file.points.reals, moved);
  moved.pop_back();
  EXPECT_EQ(ApplyCoordinates(moved, file).code(), absl::StatusCode::kInvalidArgument);
}

TEST(ToWireParameters, DefaultsLeaveEveryFieldUnset) {
  const v1::SmoothingParameters wire = ToWireParameters(SmoothingParams());
  EXPECT_EQ(wire.method(), v1::METHOD_GETME);
  v1::SmoothingParameters expected;
  expected.set_method(v1::METHOD_GETME);
  EXPECT_EQ(wire.SerializeAsString(), expected.SerializeAsString());
}

TEST(ToWireParameters, ChangedFieldsAreSent) {
  SmoothingParams params;
  params.method = Method::kSmartLaplace;
  params.UseLiteralPaperAlgorithm();
  params.fix_boundary = false;
  params.untangle = false;
  params.sequential_max_iterations = 77;
  params.simultaneous_sigma_max[TypeIndex(ElementType::kPrism)] = 1.7;
  params.threads = 3;
  const v1::SmoothingParameters wire = ToWireParameters(params);
  EXPECT_EQ(wire.method(), v1::METHOD_SMART_LAPLACE);
  ASSERT_TRUE(wire.has_simultaneous_backtracking_steps());
  EXPECT_EQ(wire.simultaneous_backtracking_steps(), 0);
  ASSERT_TRUE(wire.has_sequential_transform_blockers());
  EXPECT_FALSE(wire.sequential_transform_blockers());
  EXPECT_TRUE(wire.free_boundary());
  ASSERT_TRUE(wire.has_untangle());
  EXPECT_FALSE(wire.untangle());
  EXPECT_EQ(wire.sequential_max_iterations(), 77);
  EXPECT_FALSE(wire.has_simultaneous_max_iterations());
  EXPECT_TRUE(wire.simultaneous_sigma_max().has_prism());
  EXPECT_FALSE(wire.simultaneous_sigma_max().has_tetrahedron());
  EXPECT_EQ(wire.simultaneous_sigma_max().prism(), 1.7);
  EXPECT_FALSE(wire.has_simultaneous_sigma_min());
  EXPECT_EQ(wire.threads(), 3);
}

TEST(FromWire, QualityMapsWedgesToPrismsAndProgressFields) {
  v1::QualityReport report;
  report.set_elements(5);
  report.set_q_min(0.25);
  report.set_invalid_elements(1);
  report.add_first_invalid_elements(3);
  report.mutable_wedges()->set_count(2);
  report.mutable_wedges()->set_q_min(0.5);
  report.mutable_pyramids()->set_count(1);
  report.mutable_pyramids()->set_q_mean(0.75);
  report.add_histogram(4);
  report.add_histogram(1);
  const MeshQuality quality = FromWireQuality(report);
  EXPECT_EQ(quality.elements, 5);
  EXPECT_EQ(quality.invalid, 1);
  EXPECT_EQ(quality.first_invalid, (std::vector<ElementId>{3}));
  EXPECT_EQ(quality.by_type[TypeIndex(ElementType::kPrism)].count, 2);
  EXPECT_EQ(quality.by_type[TypeIndex(ElementType::kPrism)].q_min, 0.5);
  EXPECT_EQ(quality.by_type[TypeIndex(ElementType::kPyramid)].q_mean, 0.75);
  EXPECT_EQ(quality.by_type[TypeIndex(ElementType::kTetrahedron)].q_min, 1.0);  // no tets
  EXPECT_EQ(quality.histogram, (std::vector<std::int64_t>{4, 1}));

  v1::ProgressEvent wire_event;
  wire_event.set_phase(v1::PHASE_SEQUENTIAL);
  wire_event.set_iteration(3000);
  wire_event.set_q_min(0.4);
  wire_event.set_q_mean(0.8);
  wire_event.set_reverted_nodes(2);
  wire_event.set_phase_done(true);
  const ProgressEvent event = FromWireProgress(wire_event);
  EXPECT_EQ(event.phase, Phase::kSequential);
  EXPECT_EQ(event.iteration, 3000);
  EXPECT_EQ(event.q_min, 0.4);
  EXPECT_EQ(event.q_mean, 0.8);
  EXPECT_EQ(event.reverted_nodes, 2);
  EXPECT_TRUE(event.phase_done);
}

}  // namespace
}  // namespace getme::remote
