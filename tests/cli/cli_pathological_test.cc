// Pathological but well-formed meshes through the `getme smooth` executable (issue 7, hostile
// input): each gets a clear answer — success with a valid, NaN-free result, or exit status 1 with
// a message naming what is wrong and no output file — and never a hang (ctest's timeout) or a
// NaN in any output number.

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "formats/grid_mesh.h"
#include "formats/vtk_reader.h"
#include "formats/vtk_writer.h"
#include "json_test_parser.h"
#include "run_getme.h"

namespace getme::cli {
namespace {

using testing::JsonValue;
using testing::RunGetme;
using testing::TempPath;

constexpr int kTetra = 10;
constexpr int kHexahedron = 12;

struct TestMesh {
  std::vector<std::array<double, 3>> points;
  std::vector<std::pair<int, std::vector<std::int64_t>>> cells;  // VTK type, VTK node order
  std::vector<int> fixed;                                        // empty: no `fixed` array
};

// An n×n×n block of unit hexahedra scaled by `scale`, nodes numbered x fastest.
TestMesh HexBlock(int n, double scale = 1.0) {
  TestMesh mesh;
  const auto id = [n](int i, int j, int k) { return i + (n + 1) * (j + (n + 1) * k); };
  for (int k = 0; k <= n; ++k) {
    for (int j = 0; j <= n; ++j) {
      for (int i = 0; i <= n; ++i) mesh.points.push_back({i * scale, j * scale, k * scale});
    }
  }
  for (int k = 0; k < n; ++k) {
    for (int j = 0; j < n; ++j) {
      for (int i = 0; i < n; ++i) {
        mesh.cells.push_back(
            {kHexahedron,
             {id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k), id(i, j + 1, k), id(i, j, k + 1),
              id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1)}});
      }
    }
  }
  return mesh;
}

double SignedVolume(const TestMesh& mesh, const std::vector<std::int64_t>& tet) {
  std::array<std::array<double, 3>, 3> e;
  for (int k = 0; k < 3; ++k) {
    for (int axis = 0; axis < 3; ++axis) {
      e[k][axis] = mesh.points[tet[k + 1]][axis] - mesh.points[tet[0]][axis];
    }
  }
  return (e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) -
          e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) +
          e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0])) /
         6.0;
}

// The same block cut into six tetrahedra per hexahedron around its diagonal 0-6 (conforming:
// neighbouring hexahedra cut their shared face along the same diagonal), positively oriented.
TestMesh TetBlock(int n) {
  const TestMesh hexes = HexBlock(n);
  TestMesh mesh;
  mesh.points = hexes.points;
  constexpr int kTets[6][4] = {{0, 1, 2, 6}, {0, 2, 3, 6}, {0, 3, 7, 6},
                               {0, 7, 4, 6}, {0, 4, 5, 6}, {0, 5, 1, 6}};
  for (const auto& [type, hex] : hexes.cells) {
    for (const auto& tet : kTets) {
      std::vector<std::int64_t> nodes = {hex[tet[0]], hex[tet[1]], hex[tet[2]], hex[tet[3]]};
      if (SignedVolume(mesh, nodes) < 0) std::swap(nodes[1], nodes[2]);
      mesh.cells.push_back({kTetra, nodes});
    }
  }
  return mesh;
}

std::string WriteInput(const TestMesh& mesh, const std::string& name) {
  formats::UnstructuredGrid file;
  file.title = name;
  file.points.components = 3;
  for (const auto& point : mesh.points) {
    file.points.reals.insert(file.points.reals.end(), point.begin(), point.end());
  }
  for (const auto& [type, nodes] : mesh.cells) file.cells.Add(type, nodes);
  if (!mesh.fixed.empty()) {
    formats::DataArray fixed;
    fixed.name = "fixed";
    fixed.type = formats::VtkDataType::kInt;
    fixed.integers.assign(mesh.fixed.begin(), mesh.fixed.end());
    file.point_data.push_back(
        {formats::VtkAttributeKind::kScalars, "fixed", "default", {std::move(fixed)}});
  }
  const std::string path = TempPath(name + ".vtk");
  const absl::Status status = formats::WriteVtkFile(path, file);
  EXPECT_TRUE(status.ok()) << status;
  return path;
}

// Every value of a JSON document; a NaN or infinity is written as null (json_output.cc).
void ExpectNoNull(const JsonValue& value, const std::string& where) {
  EXPECT_NE(value.kind, JsonValue::Kind::kNull) << "null (a non-finite number) at " << where;
  for (std::size_t i = 0; i < value.array.size(); ++i) {
    ExpectNoNull(value.array[i], where + "[" + std::to_string(i) + "]");
  }
  for (const auto& [key, member] : value.object) ExpectNoNull(member, where + "." + key);
}

struct Smoothed {
  formats::UnstructuredGrid file;
  formats::GridMesh mesh;
};

// Runs `getme smooth --json` and checks a success: every stdout line JSON without a non-finite
// number, the output valid (every volume cell), with finite coordinates and quality.
Smoothed ExpectSmoothed(const TestMesh& input, const std::string& name) {
  const std::string in = WriteInput(input, name);
  const std::string out = TempPath(name + "-out.vtk");
  const testing::RunResult run = RunGetme({"smooth", in, out, "--json", "--threads", "2"});
  EXPECT_EQ(run.exit_status, 0) << run.err;
  for (const std::string& line : testing::Lines(run.out)) {
    const std::optional<JsonValue> value = testing::ParseJson(line);
    EXPECT_TRUE(value.has_value()) << "not JSON: " << line;
    if (value) ExpectNoNull(*value, "stdout");
  }
  Smoothed result;
  absl::StatusOr<formats::UnstructuredGrid> file = formats::ReadVtkFile(out);
  EXPECT_TRUE(file.ok()) << file.status();
  if (!file.ok()) return result;
  result.file = *std::move(file);
  for (const double value : result.file.points.reals) EXPECT_TRUE(std::isfinite(value));
  const formats::DataArray* valid = formats::FindArray(result.file.cell_data, "valid");
  const formats::DataArray* mean_ratio = formats::FindArray(result.file.cell_data, "mean_ratio");
  EXPECT_NE(valid, nullptr);
  EXPECT_NE(mean_ratio, nullptr);
  if (valid == nullptr || mean_ratio == nullptr) return result;
  for (std::int64_t cell = 0; cell < result.file.cells.size(); ++cell) {
    EXPECT_EQ(valid->AsDouble(cell), 1.0) << "cell " << cell;
    EXPECT_GT(mean_ratio->AsDouble(cell), 0.0) << "cell " << cell;
    EXPECT_LE(mean_ratio->AsDouble(cell), 1.0) << "cell " << cell;
  }
  absl::StatusOr<formats::GridMesh> mesh = formats::GridToMesh(result.file);
  EXPECT_TRUE(mesh.ok()) << mesh.status();
  if (mesh.ok()) result.mesh = *std::move(mesh);
  return result;
}

// Runs `getme smooth` and checks a refusal: exit status 1, the message, no output file.
void ExpectRefused(const TestMesh& input, const std::string& name,
                   const std::vector<std::string>& message_parts) {
  const std::string in = WriteInput(input, name);
  const std::string out = TempPath(name + "-out.vtk");
  const testing::RunResult run = RunGetme({"smooth", in, out, "--quiet", "--threads", "2"});
  EXPECT_EQ(run.exit_status, 1) << run.err;
  for (const std::string& part : message_parts) {
    EXPECT_NE(run.err.find(part), std::string::npos) << "'" << part << "' not in: " << run.err;
  }
  EXPECT_FALSE(std::filesystem::exists(out));
}

std::array<double, 3> NodeAt(const formats::UnstructuredGrid& file, std::int64_t node) {
  return {file.points.AsDouble(3 * node), file.points.AsDouble(3 * node + 1),
          file.points.AsDouble(3 * node + 2)};
}

TEST(CliPathological, ThePlainBlockSmoothsCleanly) { ExpectSmoothed(TetBlock(2), "plain"); }

// Two hexahedra side by side whose shared face has its nodes twice (same coordinates, other
// ids): two disconnected blocks for the engine, each with all nodes on its boundary.
TEST(CliPathological, DuplicateNodes) {
  TestMesh mesh = HexBlock(1);
  const std::int64_t offset = static_cast<std::int64_t>(mesh.points.size());
  for (std::int64_t node = 0; node < offset; ++node) {
    const auto [x, y, z] = mesh.points[node];
    mesh.points.push_back({x + 1.0, y, z});
  }
  std::vector<std::int64_t> second = mesh.cells[0].second;
  for (std::int64_t& node : second) node += offset;
  mesh.cells.push_back({kHexahedron, second});
  const Smoothed result = ExpectSmoothed(mesh, "duplicate-nodes");
  // Every node is a boundary node, fixed by default.
  for (std::int64_t node = 0; node < result.file.point_count(); ++node) {
    EXPECT_EQ(NodeAt(result.file, node), mesh.points[node]) << "node " << node;
  }
}

// The interior node of a 2×2×2 block moved into the bottom face's plane: the tetrahedra between
// it and that face have zero volume. It is free, so untangling lifts it.
TEST(CliPathological, ZeroVolumeElementsAreUntangled) {
  TestMesh mesh = TetBlock(2);
  constexpr std::int64_t kCentre = 13;
  ASSERT_EQ(mesh.points[kCentre], (std::array<double, 3>{1, 1, 1}));
  mesh.points[kCentre] = {1.0, 1.0, 0.0};
  int flat = 0;
  for (const auto& [type, nodes] : mesh.cells) flat += SignedVolume(mesh, nodes) == 0.0 ? 1 : 0;
  ASSERT_GT(flat, 0);
  const Smoothed result = ExpectSmoothed(mesh, "zero-volume");
  EXPECT_GT(NodeAt(result.file, kCentre)[2], 0.0);
}

// A tetrahedron whose four nodes are one point, beside a valid block: it is invalid and, all its
// nodes on its own boundary, cannot be untangled; the error proves it, naming the element and
// its pinned corner.
TEST(CliPathological, CollapsedElementThatCannotBeUntangled) {
  TestMesh mesh = TetBlock(1);
  const std::int64_t first = static_cast<std::int64_t>(mesh.points.size());
  for (int k = 0; k < 4; ++k) mesh.points.push_back({5.0, 5.0, 5.0});
  mesh.cells.push_back({kTetra, {first, first + 1, first + 2, first + 3}});
  ExpectRefused(mesh, "collapsed",
                {"cannot untangle: 1 invalid element has a corner with det <= 0",
                 "element 6 (tetrahedron), corner of node 8: det 0"});
}

// Three tetrahedra on one triangle (two above it, overlapping, one below): no volume mesh has a
// face of three elements, so the mesh is refused, naming the face and its elements.
TEST(CliPathological, NonManifoldFace) {
  TestMesh mesh;
  mesh.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.3, 0.3, 1}, {0.3, 0.3, -1}, {0.2, 0.2, 0.5}};
  mesh.cells = {{kTetra, {0, 1, 2, 3}}, {kTetra, {0, 2, 1, 4}}, {kTetra, {0, 1, 2, 5}}};
  ExpectRefused(mesh, "non-manifold", {"face with nodes {0, 1, 2} belongs to 3 elements"});
}

// A tetrahedron far from the block, sharing no node with it: all its nodes are boundary nodes,
// so it stays where it is; the block is smoothed as without it.
TEST(CliPathological, ElementSharingNoNodeWithTheRest) {
  TestMesh mesh = TetBlock(2);
  const std::int64_t first = static_cast<std::int64_t>(mesh.points.size());
  mesh.points.insert(mesh.points.end(), {{10, 10, 10}, {11, 10, 10}, {10, 11, 10}, {10, 10, 11}});
  mesh.cells.push_back({kTetra, {first, first + 1, first + 2, first + 3}});
  const Smoothed result = ExpectSmoothed(mesh, "isolated-element");
  for (std::int64_t node = first; node < first + 4; ++node) {
    EXPECT_EQ(NodeAt(result.file, node), mesh.points[node]) << "node " << node;
  }
}

// The first hexahedron listed twice: its outer faces would count two elements each and leave the
// boundary, letting boundary nodes move, so the mesh is refused, naming both.
TEST(CliPathological, RepeatedElement) {
  TestMesh mesh = HexBlock(2);
  mesh.cells.push_back(mesh.cells[0]);
  ExpectRefused(mesh, "repeated-element", {"repeats element 0"});
}

// Every node fixed: nothing may move, and that is a success, not an error.
TEST(CliPathological, AllNodesFixed) {
  TestMesh mesh = TetBlock(2);
  mesh.points[13] = {1.2, 0.9, 1.1};  // something a smoother would move
  mesh.fixed.assign(mesh.points.size(), 1);
  const Smoothed result = ExpectSmoothed(mesh, "all-fixed");
  for (std::int64_t node = 0; node < result.file.point_count(); ++node) {
    EXPECT_EQ(NodeAt(result.file, node), mesh.points[node]) << "node " << node;
  }
}

// Coordinates at 1e±150 and 1e±300: element quality would under- or overflow in double precision
// (lengths enter to the sixth power), so the mesh is refused with a message saying to rescale.
TEST(CliPathological, ExtremeScalesAreRefusedWithAClearMessage) {
  for (const double scale : {1e-300, 1e-150}) {
    SCOPED_TRACE(scale);
    ExpectRefused(HexBlock(2, scale), "tiny", {"below 1e-40", "rescale the mesh"});
  }
  for (const double scale : {1e150, 1e300}) {
    SCOPED_TRACE(scale);
    ExpectRefused(HexBlock(2, scale), "huge", {"beyond 1e+40", "rescale"});
  }
}

// Well inside those bounds the scale does not matter: a distorted block at 1e-20 and 1e+20
// smooths to the same shape as at 1.
TEST(CliPathological, ModerateScalesSmoothLikeUnitScale) {
  std::vector<std::vector<double>> shapes;
  for (const double scale : {1.0, 1e-20, 1e20}) {
    SCOPED_TRACE(scale);
    TestMesh mesh = TetBlock(2);
    mesh.points[13] = {1.3, 0.8, 1.2};
    for (auto& point : mesh.points) {
      for (double& c : point) c *= scale;
    }
    const Smoothed result = ExpectSmoothed(mesh, "scaled");
    std::vector<double> shape;
    for (const double value : result.file.points.reals) shape.push_back(value / scale);
    shapes.push_back(shape);
  }
  ASSERT_EQ(shapes.size(), 3u);
  for (std::size_t i = 0; i < shapes[0].size(); ++i) {
    EXPECT_NEAR(shapes[1][i], shapes[0][i], 1e-9) << i;
    EXPECT_NEAR(shapes[2][i], shapes[0][i], 1e-9) << i;
  }
}

}  // namespace
}  // namespace getme::cli
