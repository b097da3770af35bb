// `getme smooth` on Exodus files end to end: an Exodus file written by meshio smooths to exactly
// the coordinates of the VTK run of the same mesh, and --fix-physical NODESET holds that node
// set's nodes in place.

#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

#include "exodus_test_util.h"
#include "formats/exodus/exodus_writer.h"
#include "formats/mesh_file.h"
#include "run_getme.h"

namespace getme::formats {
namespace {

using cli::testing::RunGetme;
using cli::testing::RunResult;
using cli::testing::TempPath;
using testing::ExodusFixture;

MeshDocument Read(const std::string& path) {
  absl::StatusOr<MeshDocument> document = ReadMeshDocument(path);
  EXPECT_TRUE(document.ok()) << document.status();
  return document.ok() ? *std::move(document) : MeshDocument{};
}

std::vector<double> Coordinates(const MeshDocument& document) {
  std::vector<double> values;
  for (std::int64_t i = 0; i < document.grid.points.value_count(); ++i) {
    values.push_back(document.grid.points.AsDouble(i));
  }
  return values;
}

bool SameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

void ExpectSuccess(const RunResult& run) {
  EXPECT_EQ(run.exit_status, 0) << "stdout:\n" << run.out << "\nstderr:\n" << run.err;
}

const std::vector<std::string> kFlags = {"--free-boundary", "--quiet", "--threads", "2"};

std::vector<double> Smoothed(const std::string& input, const std::string& output,
                             std::vector<std::string> extra = {}) {
  std::vector<std::string> args = {"smooth", input, output};
  args.insert(args.end(), kFlags.begin(), kFlags.end());
  args.insert(args.end(), extra.begin(), extra.end());
  ExpectSuccess(RunGetme(args));
  return Coordinates(Read(output));
}

std::int64_t DifferingValues(const std::vector<double>& a, const std::vector<double>& b) {
  EXPECT_EQ(a.size(), b.size());
  std::int64_t differing = 0;
  for (std::size_t i = 0; i < std::min(a.size(), b.size()); ++i) {
    differing += SameBits(a[i], b[i]) ? 0 : 1;
  }
  return differing;
}

TEST(ExodusCli, SmoothedExodusEqualsTheVtkRun) {
  const std::string vtk = std::string(GETME_TEST_DATA) + "/hybrid-example.vtk";
  const std::string exodus = ExodusFixture("hybrid_example_meshio.exo");
  const std::vector<double> reference = Smoothed(vtk, TempPath("reference.vtk"));
  ASSERT_EQ(reference.size(), 768u * 3);
  EXPECT_GT(DifferingValues(reference, Coordinates(Read(vtk))), 0);  // it did smooth

  EXPECT_EQ(DifferingValues(Smoothed(exodus, TempPath("out.exo")), reference), 0);
  EXPECT_EQ(DifferingValues(Smoothed(exodus, TempPath("out.vtk")), reference), 0);
  // And the Exodus output keeps the input's blocks.
  const MeshDocument input = Read(exodus);
  const MeshDocument output = Read(TempPath("out.exo"));
  ASSERT_TRUE(output.exodus.has_value());
  EXPECT_EQ(output.exodus->blocks, input.exodus->blocks);
  EXPECT_EQ(testing::CellRows(output.grid.cells), testing::CellRows(input.grid.cells));
}

TEST(ExodusCli, FixedNodeSetKeepsItsNodes) {
  const std::string vtk = std::string(GETME_TEST_DATA) + "/hybrid-example.vtk";
  const std::vector<double> original = Coordinates(Read(vtk));
  const std::vector<double> free_run = Smoothed(vtk, TempPath("free.vtk"));
  // Every third node the free run moves: held by a node set named "held".
  MeshDocument document = Read(ExodusFixture("hybrid_example_meshio.exo"));
  ASSERT_TRUE(document.exodus.has_value());
  ExodusNodeSet held;
  held.id = 42;
  held.name = "held";
  for (std::int64_t node = 0; node < document.grid.point_count(); ++node) {
    bool moved = false;
    for (int c = 0; c < 3; ++c) moved |= !SameBits(free_run[3 * node + c], original[3 * node + c]);
    if (moved && node % 3 == 0) held.nodes.push_back(node);
  }
  ASSERT_GT(held.nodes.size(), 20u);
  document.exodus->node_sets.push_back(held);
  const std::string input = TempPath("with-node-set.exo");
  ASSERT_TRUE(WriteExodus(input, document, document.as_read).ok());

  for (const char* group : {"held", "42"}) {
    SCOPED_TRACE(group);
    const std::string output = TempPath("held.exo");
    const std::vector<double> smoothed = Smoothed(input, output, {"--fix-physical", group});
    std::int64_t moved_held = 0, moved_others = 0;
    std::vector<bool> is_held(original.size() / 3, false);
    for (const std::int64_t node : held.nodes) is_held[node] = true;
    for (std::size_t node = 0; node < is_held.size(); ++node) {
      bool moved = false;
      for (int c = 0; c < 3; ++c)
        moved |= !SameBits(smoothed[3 * node + c], original[3 * node + c]);
      (is_held[node] ? moved_held : moved_others) += moved ? 1 : 0;
    }
    EXPECT_EQ(moved_held, 0);
    EXPECT_GT(moved_others, 100);
    const MeshDocument result = Read(output);
    ASSERT_TRUE(result.exodus.has_value());
    ASSERT_EQ(result.exodus->node_sets.size(), 1u);
    EXPECT_EQ(result.exodus->node_sets[0], held);
  }
}

TEST(ExodusCli, UnknownGroupNamesTheSets) {
  const RunResult run = RunGetme({"smooth", ExodusFixture("hybrid.exo"), TempPath("x.exo"),
                                  "--fix-physical", "outlet", "--quiet"});
  EXPECT_EQ(run.exit_status, 1);
  EXPECT_NE(run.err.find("no node set, side set or element block 'outlet' (by name or id); node "
                         "sets: clamp (5), top (6); side sets: inlet (1), wall (2)"),
            std::string::npos)
      << run.err;
}

TEST(ExodusCli, AsciiExodusOutputIsRefused) {
  const RunResult run =
      RunGetme({"convert", ExodusFixture("hybrid.exo"), TempPath("ascii.exo"), "--ascii"});
  EXPECT_NE(run.exit_status, 0);
  EXPECT_NE(run.err.find("Exodus II output is binary only (netCDF, written by the Exodus "
                         "library)"),
            std::string::npos)
      << run.err;
}

}  // namespace
}  // namespace getme::formats
