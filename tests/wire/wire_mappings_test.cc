// Engine <-> wire mappings of meshes, parameters, quality and progress, checked against
// hand-written expectations (VTK wedge order, parameter defaults, wedges as prisms).

#include <gtest/gtest.h>

#include <array>
#include <vector>

#include "getme_wire/engine_mesh.h"
#include "getme_wire/enums.h"
#include "getme_wire/params.h"
#include "getme_wire/progress.h"
#include "getme_wire/reports.h"

namespace getme::wire {
namespace {

std::vector<std::uint32_t> Values(const google::protobuf::RepeatedField<std::uint32_t>& field) {
  return {field.begin(), field.end()};
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
  // The literal algorithm has no polish: the switch is sent, as false.
  ASSERT_TRUE(wire.has_polish());
  EXPECT_FALSE(wire.polish());
  EXPECT_FALSE(wire.has_polish_max_sweeps());
  // ...and picks one element at a time.
  ASSERT_TRUE(wire.has_sequential_batch());
  EXPECT_EQ(wire.sequential_batch(), 1);
  EXPECT_FALSE(wire.has_sequential_batch_band());
}

TEST(ToEngineParams, SequentialBatchFieldsRoundTrip) {
  SmoothingParams params;
  params.sequential_batch = 256;
  params.sequential_batch_band = 0.05;
  params.sequential_batch_elements = 100;
  const v1::SmoothingParameters wire = ToWireParameters(params);
  EXPECT_EQ(wire.sequential_batch(), 256);
  EXPECT_EQ(wire.sequential_batch_band(), 0.05);
  EXPECT_EQ(wire.sequential_batch_elements(), 100);
  absl::StatusOr<SmoothingParams> back = ToEngineParams(wire, 1);
  ASSERT_TRUE(back.ok()) << back.status();
  EXPECT_EQ(back->sequential_batch, 256);
  EXPECT_EQ(back->sequential_batch_band, 0.05);
  EXPECT_EQ(back->sequential_batch_elements, 100);
  // `literal` sets one pick at a time; an explicit batch given with it still wins, as every
  // explicit field does.
  v1::SmoothingParameters literal;
  literal.set_literal(true);
  back = ToEngineParams(literal, 1);
  ASSERT_TRUE(back.ok()) << back.status();
  EXPECT_EQ(back->sequential_batch, 1);
  literal.set_sequential_batch(8);
  back = ToEngineParams(literal, 1);
  ASSERT_TRUE(back.ok()) << back.status();
  EXPECT_EQ(back->sequential_batch, 8);
  // Out of range: the engine names the field, the wire says where it sits.
  v1::SmoothingParameters bad;
  bad.set_sequential_batch(0);
  back = ToEngineParams(bad, 1);
  ASSERT_FALSE(back.ok());
  EXPECT_EQ(back.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_NE(back.status().message().find("parameters: parameter sequential_batch = 0"),
            std::string::npos)
      << back.status();
}

TEST(ToEngineParams, PolishAndUntangleFieldsRoundTrip) {
  SmoothingParams params;
  params.polish_tolerance = 3e-5;
  params.polish_final_tolerance = 7e-4;
  params.polish_max_sweeps = 17;
  params.polish_node_tolerance = 2e-7;
  params.polish_backtracking_steps = 6;
  params.simultaneous_handoff_window = 9;
  params.simultaneous_handoff_gain = 5e-5;
  params.sequential_handoff_window = 1234;
  params.polish_over_relaxation = 1.5;
  params.polish_worst_exponent = 4.0;
  params.polish_worst_tolerance = 2e-3;
  params.polish_worst_max_sweeps = 9;
  params.polish_cluster_trigger = 0.5;
  params.polish_cluster_band = 0.1;
  params.polish_cluster_exponent = 12.0;
  params.polish_cluster_tolerance = 1e-3;
  params.polish_cluster_max_rounds = 7;
  params.polish_cluster_iterations = 50;
  params.polish_cluster_ascent_iterations = 0;
  const v1::SmoothingParameters wire = ToWireParameters(params);
  EXPECT_FALSE(wire.has_polish());  // on is the default: not sent
  EXPECT_EQ(wire.polish_max_sweeps(), 17);
  absl::StatusOr<SmoothingParams> back = ToEngineParams(wire, 1);
  ASSERT_TRUE(back.ok()) << back.status();
  EXPECT_TRUE(back->polish);
  EXPECT_EQ(back->polish_tolerance, 3e-5);
  EXPECT_EQ(back->polish_final_tolerance, 7e-4);
  EXPECT_EQ(back->polish_max_sweeps, 17);
  EXPECT_EQ(back->polish_node_tolerance, 2e-7);
  EXPECT_EQ(back->polish_backtracking_steps, 6);
  EXPECT_EQ(back->simultaneous_handoff_window, 9);
  EXPECT_EQ(back->simultaneous_handoff_gain, 5e-5);
  EXPECT_EQ(back->sequential_handoff_window, 1234);
  EXPECT_EQ(back->polish_over_relaxation, 1.5);
  EXPECT_EQ(back->polish_worst_exponent, 4.0);
  EXPECT_EQ(back->polish_worst_tolerance, 2e-3);
  EXPECT_EQ(back->polish_worst_max_sweeps, 9);
  EXPECT_EQ(back->polish_cluster_trigger, 0.5);
  EXPECT_EQ(back->polish_cluster_band, 0.1);
  EXPECT_EQ(back->polish_cluster_exponent, 12.0);
  EXPECT_EQ(back->polish_cluster_tolerance, 1e-3);
  EXPECT_EQ(back->polish_cluster_max_rounds, 7);
  EXPECT_EQ(back->polish_cluster_iterations, 50);
  EXPECT_EQ(back->polish_cluster_ascent_iterations, 0);
  // Turning the stage off is a value (0), not an absent field: it must cross the wire.
  SmoothingParams no_cluster;
  no_cluster.polish_cluster_trigger = 0.0;
  ASSERT_TRUE(ToWireParameters(no_cluster).has_polish_cluster_trigger());
  back = ToEngineParams(ToWireParameters(no_cluster), 1);
  ASSERT_TRUE(back.ok()) << back.status();
  EXPECT_EQ(back->polish_cluster_trigger, 0.0);
  v1::SmoothingParameters bad_exponent;
  bad_exponent.set_polish_cluster_exponent(100.0);
  const absl::StatusOr<SmoothingParams> refused = ToEngineParams(bad_exponent, 1);
  EXPECT_EQ(refused.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_NE(refused.status().message().find("polish_cluster_exponent"), std::string::npos)
      << refused.status();

  params = SmoothingParams();
  params.untangle_free_boundary = true;
  ASSERT_TRUE(ToWireParameters(params).has_untangle_free_boundary());
  back = ToEngineParams(ToWireParameters(params), 1);
  ASSERT_TRUE(back.ok()) << back.status();
  EXPECT_TRUE(back->untangle_free_boundary);

  v1::SmoothingParameters off;
  off.set_polish(false);
  back = ToEngineParams(off, 1);
  ASSERT_TRUE(back.ok()) << back.status();
  EXPECT_FALSE(back->polish);

  v1::SmoothingParameters bad;
  bad.set_polish_max_sweeps(-2);
  back = ToEngineParams(bad, 1);
  EXPECT_EQ(back.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_NE(back.status().message().find("polish_max_sweeps = -2"), std::string::npos)
      << back.status();
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
}  // namespace getme::wire
