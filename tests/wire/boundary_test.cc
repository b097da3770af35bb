// The boundary on the wire (issue 15): boundary, its older spelling free_boundary,
// feature_angle_degrees and keep_layers to the engine's parameters and back, every bad value or
// contradicting combination refused with INVALID_ARGUMENT naming the fields, and the boundary
// slide's and kept layers' reports from engine and surface/ to the wire and back.

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "getme_wire/boundary_reports.h"
#include "getme_wire/enums.h"
#include "getme_wire/params.h"
#include "getme_wire/reports.h"

namespace getme::wire {
namespace {

SmoothingParams Accepted(const v1::SmoothingParameters& wire) {
  absl::StatusOr<SmoothingParams> params = ToEngineParams(wire, 1);
  EXPECT_TRUE(params.ok()) << params.status();
  return params.ok() ? *params : SmoothingParams();
}

// The message of the refusal, after checking it is one: INVALID_ARGUMENT naming every field in
// `fields`.
std::string Refusal(const v1::SmoothingParameters& wire,
                    std::initializer_list<const char*> fields) {
  const absl::StatusOr<SmoothingParams> params = ToEngineParams(wire, 1);
  EXPECT_EQ(params.status().code(), absl::StatusCode::kInvalidArgument) << params.status();
  const std::string message(params.status().message());
  for (const char* field : fields) {
    EXPECT_NE(message.find(field), std::string::npos) << "'" << field << "' not in: " << message;
  }
  return message;
}

TEST(BoundaryParameters, EachBoundarySetsTheEngineSwitches) {
  v1::SmoothingParameters wire;
  SmoothingParams params = Accepted(wire);
  EXPECT_TRUE(params.fix_boundary);
  EXPECT_FALSE(params.slide_boundary);

  wire.set_boundary(v1::BOUNDARY_SLIDE);
  params = Accepted(wire);
  EXPECT_TRUE(params.fix_boundary);  // the engine's "held or sliding"
  EXPECT_TRUE(params.slide_boundary);
  EXPECT_EQ(params.feature_angle_degrees, SmoothingParams().feature_angle_degrees);

  wire.set_boundary(v1::BOUNDARY_FREE);
  params = Accepted(wire);
  EXPECT_FALSE(params.fix_boundary);
  EXPECT_FALSE(params.slide_boundary);

  wire.set_boundary(v1::BOUNDARY_FIXED);
  params = Accepted(wire);
  EXPECT_TRUE(params.fix_boundary);
  EXPECT_FALSE(params.slide_boundary);
}

TEST(BoundaryParameters, FreeBoundaryStaysTheSpellingOfBoundaryFree) {
  v1::SmoothingParameters wire;
  wire.set_free_boundary(true);
  EXPECT_FALSE(Accepted(wire).fix_boundary);
  wire.set_boundary(v1::BOUNDARY_FREE);  // both spellings at once agree
  EXPECT_FALSE(Accepted(wire).fix_boundary);
  wire.set_free_boundary(false);
  wire.set_boundary(v1::BOUNDARY_SLIDE);  // "not free" agrees with sliding
  EXPECT_TRUE(Accepted(wire).slide_boundary);
  wire.clear_boundary();
  EXPECT_TRUE(Accepted(wire).fix_boundary);
}

TEST(BoundaryParameters, ContradictingSpellingsAreRefusedNamingBoth) {
  v1::SmoothingParameters wire;
  wire.set_free_boundary(true);
  wire.set_boundary(v1::BOUNDARY_SLIDE);
  EXPECT_NE(
      Refusal(wire, {"parameters.free_boundary = true", "parameters.boundary = BOUNDARY_SLIDE"})
          .find("contradicts"),
      std::string::npos);
  wire.set_boundary(v1::BOUNDARY_FIXED);
  Refusal(wire, {"parameters.free_boundary = true", "parameters.boundary = BOUNDARY_FIXED"});
  wire.set_free_boundary(false);
  wire.set_boundary(v1::BOUNDARY_FREE);
  Refusal(wire, {"parameters.free_boundary = false", "parameters.boundary = BOUNDARY_FREE"});
}

TEST(BoundaryParameters, UnknownBoundaryIsRefusedByNumber) {
  v1::SmoothingParameters wire;
  wire.set_boundary(static_cast<v1::Boundary>(9));
  Refusal(wire, {"parameters.boundary = 9", "getme.v1.Boundary"});
}

TEST(BoundaryParameters, FeatureAngleOutOfRangeIsRefusedByName) {
  v1::SmoothingParameters wire;
  wire.set_boundary(v1::BOUNDARY_SLIDE);
  wire.set_feature_angle_degrees(30.0);
  EXPECT_EQ(Accepted(wire).feature_angle_degrees, 30.0);
  for (const double bad : {200.0, -1.0, std::nan("")}) {
    wire.set_feature_angle_degrees(bad);
    Refusal(wire, {"feature_angle_degrees", "[0, 180]"});
  }
  wire.set_feature_angle_degrees(180.0);  // the range's ends are allowed
  EXPECT_EQ(Accepted(wire).feature_angle_degrees, 180.0);
  wire.set_feature_angle_degrees(0.0);
  EXPECT_EQ(Accepted(wire).feature_angle_degrees, 0.0);
}

TEST(BoundaryParameters, FeatureAngleWithoutASlidingBoundaryIsRefused) {
  // As the CLI refuses --feature-angle without --boundary slide: the caller expected a slide.
  v1::SmoothingParameters wire;
  wire.set_feature_angle_degrees(30.0);
  Refusal(wire, {"parameters.feature_angle_degrees", "BOUNDARY_SLIDE", "BOUNDARY_FIXED"});
  wire.set_boundary(v1::BOUNDARY_FREE);
  Refusal(wire, {"parameters.feature_angle_degrees", "BOUNDARY_FREE"});
}

TEST(BoundaryParameters, KeptLayersNeedAHeldOrSlidingBoundary) {
  v1::SmoothingParameters wire;
  wire.set_keep_layers(true);
  EXPECT_TRUE(Accepted(wire).keep_layers);
  wire.set_boundary(v1::BOUNDARY_SLIDE);
  SmoothingParams params = Accepted(wire);
  EXPECT_TRUE(params.keep_layers);
  EXPECT_TRUE(params.slide_boundary);

  wire.set_boundary(v1::BOUNDARY_FREE);
  Refusal(wire, {"parameters.keep_layers = true", "parameters.boundary = BOUNDARY_FREE"});
  wire.clear_boundary();
  wire.set_free_boundary(true);
  Refusal(wire, {"parameters.keep_layers = true", "parameters.free_boundary = true"});
  wire.set_keep_layers(false);  // asked off explicitly: nothing to refuse
  EXPECT_FALSE(Accepted(wire).keep_layers);
}

TEST(BoundaryParameters, EngineParametersRoundTrip) {
  SmoothingParams slide;
  slide.slide_boundary = true;
  slide.feature_angle_degrees = 30.0;
  slide.keep_layers = true;
  const v1::SmoothingParameters wire = ToWireParameters(slide);
  EXPECT_EQ(wire.boundary(), v1::BOUNDARY_SLIDE);
  EXPECT_FALSE(wire.has_free_boundary());
  EXPECT_EQ(wire.feature_angle_degrees(), 30.0);
  EXPECT_TRUE(wire.keep_layers());
  const SmoothingParams back = Accepted(wire);
  EXPECT_TRUE(back.fix_boundary);
  EXPECT_TRUE(back.slide_boundary);
  EXPECT_EQ(back.feature_angle_degrees, 30.0);
  EXPECT_TRUE(back.keep_layers);

  // A free boundary keeps its older spelling, which servers that predate the enum understand.
  SmoothingParams free;
  free.fix_boundary = false;
  const v1::SmoothingParameters free_wire = ToWireParameters(free);
  EXPECT_EQ(free_wire.boundary(), v1::BOUNDARY_UNSPECIFIED);
  EXPECT_TRUE(free_wire.free_boundary());
  EXPECT_FALSE(Accepted(free_wire).fix_boundary);

  // Held layers on a held boundary: no boundary field, keep_layers only.
  SmoothingParams held_layers;
  held_layers.keep_layers = true;
  const v1::SmoothingParameters held_wire = ToWireParameters(held_layers);
  EXPECT_EQ(held_wire.boundary(), v1::BOUNDARY_UNSPECIFIED);
  EXPECT_FALSE(held_wire.has_feature_angle_degrees());
  EXPECT_TRUE(Accepted(held_wire).keep_layers);
}

TEST(BoundaryEnums, EngineSwitchesNameTheirBoundary) {
  SmoothingParams params;
  EXPECT_EQ(ToWireBoundary(params), v1::BOUNDARY_FIXED);
  params.slide_boundary = true;
  EXPECT_EQ(ToWireBoundary(params), v1::BOUNDARY_SLIDE);
  params.slide_boundary = false;
  params.fix_boundary = false;
  EXPECT_EQ(ToWireBoundary(params), v1::BOUNDARY_FREE);
  EXPECT_STREQ(BoundaryName(v1::BOUNDARY_FIXED), "fixed");
  EXPECT_STREQ(BoundaryName(v1::BOUNDARY_SLIDE), "slide");
  EXPECT_STREQ(BoundaryName(v1::BOUNDARY_FREE), "free");
  EXPECT_STREQ(BoundaryName(v1::BOUNDARY_UNSPECIFIED), "unspecified");
  EXPECT_STREQ(BoundaryName(static_cast<v1::Boundary>(9)), "unspecified");
}

surface::LayerReport SampleLayerReport() {
  surface::LayerReport layers;
  layers.columns = 36;
  layers.column_elements = 360;
  layers.layer_nodes = 250;
  layers.layers = 10;
  layers.conflicting_nodes = 3;
  layers.ends_tetrahedron = 1;
  layers.ends_pyramid = 2;
  layers.ends_prism_side = 4;
  layers.ends_isotropic = 5;
  layers.ends_taken = 6;
  layers.ends_boundary = 18;
  layers.before = {0.01, 0.011, 0.012, 8.5, 0.2, 0.4};
  layers.after = {0.0101, 0.0111, 0.0121, 1.25, 0.3, 0.5};
  layers.max_height_change = 0.004;
  return layers;
}

void ExpectSameState(const surface::LayerState& actual, const surface::LayerState& expected) {
  EXPECT_EQ(actual.first_min, expected.first_min);
  EXPECT_EQ(actual.first_mean, expected.first_mean);
  EXPECT_EQ(actual.first_max, expected.first_max);
  EXPECT_EQ(actual.mean_lean_degrees, expected.mean_lean_degrees);
  EXPECT_EQ(actual.q_min, expected.q_min);
  EXPECT_EQ(actual.q_mean, expected.q_mean);
}

TEST(BoundaryReports, SlideAndLayerReportsRoundTrip) {
  SmoothingResult engine;
  engine.iterations_layers = 4;
  engine.boundary_slide = BoundarySlideSummary{120, 97, 3.5e-12, 250};
  v1::SmoothResult wire = ToWireSmoothResult(engine, {}, {}, WireMeshIds{});
  wire.set_boundary(v1::BOUNDARY_SLIDE);
  SurfaceReports reports;
  reports.boundary_surface = surface::BoundarySurfaceCounts{48, 12, 8, 3, 2};
  reports.layers = SampleLayerReport();
  AddSurfaceReports(reports, wire);
  EXPECT_EQ(wire.iterations_layers(), 4);
  EXPECT_EQ(wire.boundary_slide().slid_nodes(), 97);
  EXPECT_EQ(wire.boundary_slide().corners(), 8);
  EXPECT_EQ(wire.layers().ends_other_column(), 6);

  // Through the bytes, as a client receives it.
  v1::SmoothResult received;
  ASSERT_TRUE(received.ParseFromString(wire.SerializeAsString()));
  const SmoothingResult result = FromWireResult(received);
  EXPECT_EQ(result.iterations_layers, 4);
  ASSERT_TRUE(result.boundary_slide.has_value());
  EXPECT_EQ(result.boundary_slide->sliding_nodes, 120);
  EXPECT_EQ(result.boundary_slide->slid_nodes, 97);
  EXPECT_EQ(result.boundary_slide->max_distance, 3.5e-12);
  EXPECT_EQ(result.boundary_slide->layer_nodes, 250);
  const SurfaceReports back = FromWireSurfaceReports(received);
  ASSERT_TRUE(back.boundary_surface.has_value());
  EXPECT_EQ(back.boundary_surface->feature_edges, 48);
  EXPECT_EQ(back.boundary_surface->feature_curves, 12);
  EXPECT_EQ(back.boundary_surface->corners, 8);
  EXPECT_EQ(back.boundary_surface->surface_groups, 3);
  EXPECT_EQ(back.boundary_surface->interior_grouped_faces, 2);
  ASSERT_TRUE(back.layers.has_value());
  const surface::LayerReport& layers = *back.layers;
  const surface::LayerReport expected = SampleLayerReport();
  EXPECT_EQ(layers.columns, expected.columns);
  EXPECT_EQ(layers.column_elements, expected.column_elements);
  EXPECT_EQ(layers.layer_nodes, expected.layer_nodes);
  EXPECT_EQ(layers.layers, expected.layers);
  EXPECT_EQ(layers.conflicting_nodes, expected.conflicting_nodes);
  EXPECT_EQ(layers.ends_tetrahedron, expected.ends_tetrahedron);
  EXPECT_EQ(layers.ends_pyramid, expected.ends_pyramid);
  EXPECT_EQ(layers.ends_prism_side, expected.ends_prism_side);
  EXPECT_EQ(layers.ends_isotropic, expected.ends_isotropic);
  EXPECT_EQ(layers.ends_taken, expected.ends_taken);
  EXPECT_EQ(layers.ends_boundary, expected.ends_boundary);
  ExpectSameState(layers.before, expected.before);
  ExpectSameState(layers.after, expected.after);
  EXPECT_EQ(layers.max_height_change, expected.max_height_change);
}

TEST(BoundaryReports, OnlyWhatTheRunHadComesBack) {
  // Kept layers on a held boundary: the engine's slide summary (layer nodes) and the layers,
  // but no surface counts, as the CLI reports them only with --boundary slide.
  SmoothingResult engine;
  engine.boundary_slide = BoundarySlideSummary{0, 0, 0.0, 250};
  v1::SmoothResult wire = ToWireSmoothResult(engine, {}, {}, WireMeshIds{});
  wire.set_boundary(v1::BOUNDARY_FIXED);
  SurfaceReports reports;
  reports.layers = SampleLayerReport();
  AddSurfaceReports(reports, wire);
  SurfaceReports back = FromWireSurfaceReports(wire);
  EXPECT_FALSE(back.boundary_surface.has_value());
  EXPECT_TRUE(back.layers.has_value());
  EXPECT_EQ(FromWireResult(wire).boundary_slide->layer_nodes, 250);

  // A plain run: nothing.
  const v1::SmoothResult plain = ToWireSmoothResult(SmoothingResult(), {}, {}, WireMeshIds{});
  EXPECT_FALSE(plain.has_boundary_slide());
  EXPECT_FALSE(plain.has_layers());
  EXPECT_FALSE(FromWireResult(plain).boundary_slide.has_value());
  back = FromWireSurfaceReports(plain);
  EXPECT_FALSE(back.boundary_surface.has_value());
  EXPECT_FALSE(back.layers.has_value());
}

}  // namespace
}  // namespace getme::wire
