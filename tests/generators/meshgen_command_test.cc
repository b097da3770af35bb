#include "getme/meshgen/meshgen_command.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace getme::meshgen {
namespace {

absl::StatusOr<MeshgenCommand> Parse(std::vector<std::string> args) {
  return ParseMeshgenCommand(args);
}

TEST(MeshgenCommandTest, ParsesKindPathSizeAndSeed) {
  absl::StatusOr<MeshgenCommand> command =
      Parse({"hybrid", "out.vtk", "--size", "7,6,9", "--seed", "42", "--distortion", "0.25"});
  ASSERT_TRUE(command.ok()) << command.status();
  EXPECT_EQ(command->kind, MeshKind::kHybridBlock);
  EXPECT_EQ(command->output_path, "out.vtk");
  EXPECT_EQ(command->nx, 7);
  EXPECT_EQ(command->ny, 6);
  EXPECT_EQ(command->nz, 9);
  EXPECT_EQ(command->seed, 42u);
  EXPECT_EQ(command->distortion, 0.25);
  EXPECT_FALSE(command->binary);
}

TEST(MeshgenCommandTest, SingleSizeAppliesToAllAxesAndVesselOptionsArePassedOn) {
  absl::StatusOr<MeshgenCommand> command =
      Parse({"--size", "5", "vessel", "v.vtk", "--mesh-size", "0.3", "--layers", "4",
             "--layer-height-ratio", "0.02", "--bend-angle", "0.5", "--seed", "9", "--binary",
             "--fix-wall"});
  ASSERT_TRUE(command.ok()) << command.status();
  EXPECT_TRUE(command->vessel.fix_outer_wall);
  EXPECT_EQ(command->kind, MeshKind::kVessel);
  EXPECT_EQ(command->nx, 5);
  EXPECT_EQ(command->nz, 5);
  EXPECT_EQ(command->vessel.mesh_size, 0.3);
  EXPECT_EQ(command->vessel.layers, 4);
  EXPECT_EQ(command->vessel.layer_height_ratio, 0.02);
  EXPECT_EQ(command->vessel.bend_angle, 0.5);
  EXPECT_EQ(command->vessel.seed, 9u);
  EXPECT_TRUE(command->binary);
}

TEST(MeshgenCommandTest, ArteryOptionsArePassedOn) {
  absl::StatusOr<MeshgenCommand> command = Parse({"artery",
                                                  "a.vtk",
                                                  "--mesh-size",
                                                  "0.5",
                                                  "--layers",
                                                  "8",
                                                  "--outer-layers",
                                                  "0",
                                                  "--first-layer-ratio",
                                                  "0.002",
                                                  "--growth-ratio",
                                                  "1.3",
                                                  "--branches",
                                                  "3",
                                                  "--helix-radius",
                                                  "1.5",
                                                  "--turn-angle",
                                                  "2",
                                                  "--taper",
                                                  "0.2",
                                                  "--stenosis",
                                                  "0.4",
                                                  "--branch-radius-ratio",
                                                  "0.5",
                                                  "--branch-length",
                                                  "2.5",
                                                  "--radius",
                                                  "1.5",
                                                  "--length",
                                                  "9",
                                                  "--seed",
                                                  "4",
                                                  "--junction-fillet",
                                                  "0"});
  ASSERT_TRUE(command.ok()) << command.status();
  EXPECT_EQ(command->kind, MeshKind::kArtery);
  const ArteryOptions& a = command->artery;
  EXPECT_EQ(a.mesh_size, 0.5);
  EXPECT_EQ(a.inward_layers, 8);
  EXPECT_EQ(a.outward_layers, 0);
  EXPECT_EQ(a.first_layer_ratio, 0.002);
  EXPECT_EQ(a.growth_ratio, 1.3);
  EXPECT_EQ(a.branches, 3);
  EXPECT_EQ(a.helix_radius, 1.5);
  EXPECT_EQ(a.turn_angle, 2.0);
  EXPECT_EQ(a.taper, 0.2);
  EXPECT_EQ(a.stenosis, 0.4);
  EXPECT_EQ(a.branch_radius_ratio, 0.5);
  EXPECT_EQ(a.branch_length, 2.5);
  EXPECT_EQ(a.radius, 1.5);
  EXPECT_EQ(a.length, 9.0);
  EXPECT_EQ(a.seed, 4u);
  EXPECT_EQ(a.junction_fillet, 0.0);
  // Unset options keep the artery's own defaults, not the vessel's.
  absl::StatusOr<MeshgenCommand> plain = Parse({"artery", "a.vtk"});
  ASSERT_TRUE(plain.ok());
  EXPECT_EQ(plain->artery.mesh_size, ArteryOptions{}.mesh_size);
  EXPECT_EQ(plain->artery.inward_layers, ArteryOptions{}.inward_layers);
  EXPECT_FALSE(Parse({"artery", "a.vtk", "--elements", "5000"}).ok());
}

TEST(MeshgenCommandTest, ErrorsNameTheOffendingArgument) {
  const auto message = [](std::vector<std::string> args) {
    return std::string(Parse(std::move(args)).status().message());
  };
  EXPECT_NE(message({"cube", "o.vtk"}).find("'cube'"), std::string::npos);
  EXPECT_NE(message({"hex", "o.vtk", "--size", "3,x,4"}).find("--size"), std::string::npos);
  EXPECT_NE(message({"hex", "o.vtk", "--size", "3,4"}).find("expected 1 or 3"), std::string::npos);
  EXPECT_NE(message({"hex", "o.vtk", "--seed"}).find("--seed needs a value"), std::string::npos);
  EXPECT_NE(message({"hex", "o.vtk", "--colour", "red"}).find("--colour"), std::string::npos);
  EXPECT_NE(message({"hex"}).find("KIND and OUT.vtk"), std::string::npos);
}

TEST(MeshgenCommandTest, RefusesAnOutputNameOfAnotherFormat) {
  // It writes legacy VTK only: h.vtu would hold VTK text that the VTU reader refuses.
  const absl::StatusOr<MeshgenCommand> vtu = Parse({"hybrid", "h.vtu", "--size", "3"});
  ASSERT_FALSE(vtu.ok());
  EXPECT_EQ(vtu.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_NE(vtu.status().message().find("'h.vtu'"), std::string::npos) << vtu.status();
  EXPECT_FALSE(Parse({"tet", "t.msh"}).ok());
  EXPECT_TRUE(Parse({"tet", "T.VTK"}).ok());
}

TEST(MeshgenCommandTest, GeneratesTheRequestedBlock) {
  absl::StatusOr<MeshgenCommand> command = Parse({"tet", "t.vtk", "--size", "2,3,4"});
  ASSERT_TRUE(command.ok()) << command.status();
  absl::StatusOr<Mesh> mesh = GenerateMesh(*command);
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  EXPECT_EQ(mesh->element_count(ElementType::kTetrahedron), 6 * 2 * 3 * 4);
}

TEST(MeshgenCommandTest, PaperKindsTakeAnElementTarget) {
  absl::StatusOr<MeshgenCommand> plate = Parse({"plate", "p.vtk", "--elements", "12000"});
  ASSERT_TRUE(plate.ok()) << plate.status();
  EXPECT_EQ(plate->kind, MeshKind::kPlate);
  EXPECT_EQ(plate->elements, 12000);
  EXPECT_FALSE(plate->distortion.has_value());
  absl::StatusOr<MeshgenCommand> ring =
      Parse({"ring", "r.vtk", "--elements", "20000", "--distortion", "0.1"});
  ASSERT_TRUE(ring.ok()) << ring.status();
  EXPECT_EQ(ring->kind, MeshKind::kRing);
  EXPECT_EQ(ring->distortion, 0.1);
  absl::StatusOr<MeshgenCommand> vessel = Parse({"vessel", "v.vtk", "--elements", "300000"});
  ASSERT_TRUE(vessel.ok()) << vessel.status();
  EXPECT_EQ(vessel->elements, 300000);
  // A sized vessel defaults to the paper's prism share; a given mesh size wins.
  EXPECT_EQ(vessel->vessel.mesh_size, kPaperVesselMeshSize);
  absl::StatusOr<MeshgenCommand> fine =
      Parse({"vessel", "v.vtk", "--mesh-size", "0.2", "--elements", "300000"});
  ASSERT_TRUE(fine.ok()) << fine.status();
  EXPECT_EQ(fine->vessel.mesh_size, 0.2);
  absl::StatusOr<MeshgenCommand> unsized = Parse({"vessel", "v.vtk"});
  ASSERT_TRUE(unsized.ok()) << unsized.status();
  EXPECT_EQ(unsized->vessel.mesh_size, ThinPrismVesselOptions{}.mesh_size);
}

TEST(MeshgenCommandTest, ElementTargetsAreRejectedForBlocksAndBelowOne) {
  const auto message = [](std::vector<std::string> args) {
    return std::string(Parse(std::move(args)).status().message());
  };
  EXPECT_NE(message({"hex", "o.vtk", "--elements", "1000"}).find("--size"), std::string::npos);
  EXPECT_NE(message({"plate", "o.vtk", "--elements", "0"}).find("--elements"), std::string::npos);
  EXPECT_NE(message({"plate", "o.vtk", "--elements", "many"}).find("--elements"),
            std::string::npos);
}

TEST(MeshgenCommandTest, GeneratesPlateAndRingNearTheTargetWithTheGivenDistortion) {
  for (const char* kind : {"plate", "ring"}) {
    SCOPED_TRACE(kind);
    absl::StatusOr<MeshgenCommand> regular =
        Parse({kind, "o.vtk", "--elements", "12000", "--distortion", "0"});
    absl::StatusOr<MeshgenCommand> distorted = Parse({kind, "o.vtk", "--elements", "12000"});
    ASSERT_TRUE(regular.ok() && distorted.ok());
    absl::StatusOr<Mesh> a = GenerateMesh(*regular);
    absl::StatusOr<Mesh> b = GenerateMesh(*distorted);
    ASSERT_TRUE(a.ok()) << a.status();
    ASSERT_TRUE(b.ok()) << b.status();
    EXPECT_NEAR(static_cast<double>(a->element_count()), 12000, 1200);
    EXPECT_EQ(a->element_count(), b->element_count());
    // Undistorted: every coordinate a multiple of one half (grid points and cube centres).
    EXPECT_TRUE(std::ranges::all_of(a->x(), [](double x) { return 2 * x == std::round(2 * x); }));
    EXPECT_FALSE(std::ranges::all_of(b->x(), [](double x) { return 2 * x == std::round(2 * x); }));
  }
}

}  // namespace
}  // namespace getme::meshgen
