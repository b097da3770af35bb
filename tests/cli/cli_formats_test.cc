// `getme smooth / convert / report` across file formats, end to end through the built executable.
// Inputs: a hybrid mesh (all four volume types) with boundary triangles and quads in named
// physical groups, written by gmsh's own writer (make_grouped_hybrid.py, a ctest fixture).

#include <gtest/gtest.h>

#include <cstring>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "absl/strings/match.h"
#include "absl/strings/str_split.h"
#include "absl/strings/strip.h"
#include "formats/file_io.h"
#include "formats/mesh_file.h"
#include "formats/vtk_cell_type.h"
#include "json_test_parser.h"
#include "run_getme.h"

namespace getme::cli {
namespace {

using testing::Lines;
using testing::ParseJson;
using testing::RunGetme;
using testing::RunResult;
using testing::TempPath;

std::string GroupedHybrid(const std::string& name) {
  return std::string(GETME_GROUPED_HYBRID_DIR) + "/" + name;
}

formats::MeshDocument Read(const std::string& path) {
  absl::StatusOr<formats::MeshDocument> document = formats::ReadMeshDocument(path);
  EXPECT_TRUE(document.ok()) << document.status();
  return document.ok() ? *std::move(document) : formats::MeshDocument{};
}

// Coordinates as raw doubles, point by point.
std::vector<double> Coordinates(const formats::MeshDocument& document) {
  std::vector<double> values;
  for (std::int64_t i = 0; i < document.grid.points.value_count(); ++i) {
    values.push_back(document.grid.points.AsDouble(i));
  }
  return values;
}

bool SameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

std::set<std::int64_t> NodesOfCells(const formats::MeshDocument& document,
                                    const std::vector<std::int64_t>& cells) {
  std::set<std::int64_t> nodes;
  for (const std::int64_t cell : cells) {
    for (std::int64_t k = 0; k < document.grid.cells.node_count(cell); ++k) {
      nodes.insert(document.grid.cells.nodes(cell)[k]);
    }
  }
  return nodes;
}

std::map<int, std::int64_t> CellTypeCounts(const formats::MeshDocument& document) {
  std::map<int, std::int64_t> counts;
  for (const std::uint8_t type : document.grid.cells.types) ++counts[type];
  return counts;
}

void ExpectSuccess(const RunResult& run) {
  EXPECT_EQ(run.exit_status, 0) << "stdout:\n" << run.out << "\nstderr:\n" << run.err;
}

// Every format and variant, converted from gmsh's file and smoothed with the same options,
// gives bit-identical coordinates: the readers map each format's node order to the same mesh.
TEST(CliFormats, SameMeshFromEveryFormatSmoothsIdentically) {
  const std::string source = GroupedHybrid("hybrid-groups.msh");
  const std::vector<std::string> common = {"--free-boundary", "--fix-physical", "11",
                                           "--quiet",         "--threads",      "2"};
  const std::string reference_output = TempPath("reference.vtk");
  std::vector<std::string> args = {"smooth", source, reference_output};
  args.insert(args.end(), common.begin(), common.end());
  ExpectSuccess(RunGetme(args));
  const std::vector<double> reference = Coordinates(Read(reference_output));
  ASSERT_EQ(reference.size(), 768u * 3);

  struct Variant {
    const char* name;
    std::vector<std::string> convert_flags;
    // Group 11 is "inlet": SU2 keeps the name, its markers have no Gmsh numbers.
    const char* group = "11";
  };
  const std::vector<Variant> variants = {
      {"a.vtk", {"--ascii"}},
      {"b.vtk", {"--binary"}},
      {"a.vtu", {"--ascii"}},
      {"b.vtu", {"--binary"}},
      {"z.vtu", {"--compress"}},
      {"a22.msh", {"--format", "msh2", "--ascii"}},
      {"b22.msh", {"--format", "msh2", "--binary"}},
      {"a41.msh", {"--format", "msh4", "--ascii"}},
      {"b41.msh", {"--format", "msh4", "--binary"}},
      {"a.mesh", {}},
      {"a.su2", {}, "inlet"},
      // CGNS: the Gmsh physical surfaces become boundary conditions named as the groups.
      {"a.cgns", {}, "inlet"},
  };
  for (const Variant& variant : variants) {
    SCOPED_TRACE(variant.name);
    const std::string converted = TempPath(variant.name);
    if (absl::EndsWith(variant.name, ".mesh")) {
      // The MEDIT writer puts the cell arrays beside the mesh, in a .sol file: named here so it
      // is deleted with the rest.
      TempPath(std::string(absl::StripSuffix(variant.name, ".mesh")) + ".sol");
    }
    std::vector<std::string> convert = {"convert", source, converted};
    convert.insert(convert.end(), variant.convert_flags.begin(), variant.convert_flags.end());
    ExpectSuccess(RunGetme(convert));
    const std::string smoothed = TempPath(std::string("smoothed-") + variant.name + ".vtk");
    std::vector<std::string> smooth = {"smooth", converted, smoothed};
    smooth.insert(smooth.end(), common.begin(), common.end());
    smooth[5] = variant.group;  // the --fix-physical argument
    ExpectSuccess(RunGetme(smooth));
    const std::vector<double> coordinates = Coordinates(Read(smoothed));
    ASSERT_EQ(coordinates.size(), reference.size());
    std::int64_t differing = 0;
    for (std::size_t i = 0; i < reference.size(); ++i) {
      differing += SameBits(coordinates[i], reference[i]) ? 0 : 1;
    }
    EXPECT_EQ(differing, 0);
  }
}

// --fix-physical by name holds exactly that group's nodes (with --free-boundary the rest of the
// boundary moves); the output keeps the surface cells, groups and tags, and adds the quality.
TEST(CliFormats, FixPhysicalByNameAndOutputKeepsGroups) {
  const std::string source = GroupedHybrid("hybrid-groups-22.msh");
  const std::string output = TempPath("out.msh");
  ExpectSuccess(RunGetme(
      {"smooth", source, output, "--free-boundary", "--fix-physical", "inlet", "--quiet"}));
  const formats::MeshDocument before = Read(source);
  const formats::MeshDocument after = Read(output);
  EXPECT_EQ(after.as_read.gmsh_version, formats::GmshVersion::k22);  // the input's version
  EXPECT_EQ(after.as_read.encoding, formats::Encoding::kAscii);
  EXPECT_EQ(CellTypeCounts(after), CellTypeCounts(before));

  absl::StatusOr<std::vector<std::int64_t>> inlet_before = formats::GroupCells(before, "inlet");
  absl::StatusOr<std::vector<std::int64_t>> inlet_after = formats::GroupCells(after, "inlet");
  absl::StatusOr<std::vector<std::int64_t>> walls = formats::GroupCells(before, "walls");
  ASSERT_TRUE(inlet_before.ok() && inlet_after.ok() && walls.ok());
  EXPECT_EQ(*inlet_after, *inlet_before);
  const std::set<std::int64_t> inlet_nodes = NodesOfCells(before, *inlet_before);
  std::set<std::int64_t> wall_only_nodes;
  for (const std::int64_t node : NodesOfCells(before, *walls)) {
    if (!inlet_nodes.contains(node)) wall_only_nodes.insert(node);
  }
  ASSERT_FALSE(inlet_nodes.empty());
  const std::vector<double> x0 = Coordinates(before);
  const std::vector<double> x1 = Coordinates(after);
  for (const std::int64_t node : inlet_nodes) {
    for (int c = 0; c < 3; ++c) EXPECT_TRUE(SameBits(x0[3 * node + c], x1[3 * node + c]));
  }
  std::int64_t moved_wall_nodes = 0;
  for (const std::int64_t node : wall_only_nodes) {
    for (int c = 0; c < 3; ++c) {
      if (!SameBits(x0[3 * node + c], x1[3 * node + c])) {
        ++moved_wall_nodes;
        break;
      }
    }
  }
  EXPECT_GT(moved_wall_nodes, 0) << "--free-boundary should let the unfixed walls move";

  // Quality per cell: a value for every volume element, -1 for the surface cells.
  const formats::DataArray* mean_ratio = formats::FindArray(after.grid.cell_data, "mean_ratio");
  ASSERT_NE(mean_ratio, nullptr);
  ASSERT_EQ(mean_ratio->tuple_count(), after.grid.cells.size());
  for (std::int64_t cell = 0; cell < after.grid.cells.size(); ++cell) {
    const bool volume = formats::ElementTypeOfCell(after.grid.cells.types[cell]).has_value();
    const double q = mean_ratio->AsDouble(cell);
    if (volume) {
      EXPECT_GT(q, 0.0) << "cell " << cell;
      EXPECT_LE(q, 1.0) << "cell " << cell;
    } else {
      EXPECT_EQ(q, -1.0) << "cell " << cell;
    }
  }
}

// With every boundary face a surface cell, --fix-surfaces --free-boundary holds the same nodes
// as the default (boundary fixed): the outputs agree bit for bit.
TEST(CliFormats, FixSurfacesHoldsTheMarkedBoundary) {
  const std::string source = GroupedHybrid("hybrid-groups.msh");
  const std::string by_surfaces = TempPath("surfaces.vtu");
  const std::string by_default = TempPath("default.vtu");
  ExpectSuccess(
      RunGetme({"smooth", source, by_surfaces, "--free-boundary", "--fix-surfaces", "--quiet"}));
  ExpectSuccess(RunGetme({"smooth", source, by_default, "--quiet"}));
  const std::vector<double> a = Coordinates(Read(by_surfaces));
  const std::vector<double> b = Coordinates(Read(by_default));
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) ASSERT_TRUE(SameBits(a[i], b[i])) << i;
  EXPECT_NE(a, Coordinates(Read(source)));  // and something did move
}

TEST(CliFormats, UnknownGroupNamesTheGroupsThereAre) {
  const RunResult run = RunGetme({"smooth", GroupedHybrid("hybrid-groups.msh"), TempPath("out.msh"),
                                  "--fix-physical", "outlet"});
  EXPECT_EQ(run.exit_status, 1);
  EXPECT_NE(run.err.find("outlet"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("inlet"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("walls"), std::string::npos) << run.err;
}

TEST(CliFormats, BadFormatChoicesAreNamed) {
  const std::string source = GroupedHybrid("hybrid-groups.msh");
  RunResult run = RunGetme({"smooth", source, TempPath("out.vtk"), "--format", "stl"});
  EXPECT_EQ(run.exit_status, 2);
  EXPECT_NE(run.err.find("unknown format 'stl'"), std::string::npos) << run.err;

  run = RunGetme({"smooth", source, TempPath("out.dat")});
  EXPECT_EQ(run.exit_status, 1);
  EXPECT_NE(run.err.find("cannot tell the output format"), std::string::npos) << run.err;

  run = RunGetme({"convert", source, TempPath("out.vtk"), "--compress"});
  EXPECT_EQ(run.exit_status, 1);
  EXPECT_NE(run.err.find("--compress applies to .vtu output only"), std::string::npos) << run.err;

  run = RunGetme({"convert", source, TempPath("out.mesh"), "--binary"});
  EXPECT_EQ(run.exit_status, 1);
  EXPECT_NE(run.err.find("libMeshb"), std::string::npos) << run.err;

  run = RunGetme({"quality", TempPath("missing.meshb")});
  EXPECT_EQ(run.exit_status, 1);
  EXPECT_NE(run.err.find(".meshb"), std::string::npos) << run.err;
}

// A file with a misleading extension is read as --input-format says; without an extension the
// content decides.
TEST(CliFormats, InputFormatByOptionOrContent) {
  const std::string source = GroupedHybrid("hybrid-groups-22.msh");
  const std::string plain = TempPath("mesh-without-extension");
  absl::StatusOr<std::string> bytes = formats::ReadFileBytes(source);
  ASSERT_TRUE(bytes.ok());
  ASSERT_TRUE(formats::WriteFileAtomically(plain, *bytes).ok());
  RunResult run = RunGetme({"quality", plain, "--json"});
  ExpectSuccess(run);
  const std::string misnamed = TempPath("gmsh-file.vtk");
  ASSERT_TRUE(formats::WriteFileAtomically(misnamed, *bytes).ok());
  run = RunGetme({"quality", misnamed});
  EXPECT_EQ(run.exit_status, 1);  // read as VTK, as the extension says, and refused
  run = RunGetme({"quality", misnamed, "--input-format", "msh"});
  ExpectSuccess(run);
}

std::vector<std::int64_t> JsonHistogram(const std::string& out) {
  std::optional<testing::JsonValue> value = ParseJson(out.substr(0, out.find('\n')));
  EXPECT_TRUE(value.has_value()) << out;
  std::vector<std::int64_t> histogram;
  if (!value) return histogram;
  const testing::JsonValue* entries = value->Find("histogram");
  EXPECT_NE(entries, nullptr);
  if (entries == nullptr) return histogram;
  for (const testing::JsonValue& entry : entries->array) {
    histogram.push_back(static_cast<std::int64_t>(entry.number));
  }
  return histogram;
}

// `getme report`: the plotted histograms equal `getme quality`'s of IN and OUT, the trace rows
// are the recorded progress events, and gnuplot drew an SVG and a PNG.
TEST(CliReport, DrawsHistogramsAndTrace) {
  const std::string source = GroupedHybrid("hybrid-groups.msh");
  const std::string output = TempPath("out.vtu");
  const std::string trace = TempPath("trace.jsonl");
  ExpectSuccess(RunGetme({"smooth", source, output, "--trace", trace, "--quiet"}));
  const std::string svg = TempPath("report.svg");
  const std::string data = TempPath("report.tsv");
  ExpectSuccess(RunGetme({"report", source, output, "--trace", trace, "-o", svg, "--data", data,
                          "--bins", "10", "--title", "hybrid"}));
  absl::StatusOr<std::string> picture = formats::ReadFileBytes(svg);
  ASSERT_TRUE(picture.ok());
  EXPECT_NE(picture->find("<svg"), std::string::npos);
  EXPECT_NE(picture->find("Element quality"), std::string::npos);

  absl::StatusOr<std::string> table = formats::ReadFileBytes(data);
  ASSERT_TRUE(table.ok());
  const std::vector<std::int64_t> before =
      JsonHistogram(RunGetme({"quality", source, "--json", "--bins", "10"}).out);
  const std::vector<std::int64_t> after =
      JsonHistogram(RunGetme({"quality", output, "--json", "--bins", "10"}).out);
  ASSERT_EQ(before.size(), 10u);
  std::vector<std::vector<std::string>> histogram_rows, trace_rows;
  int block = -1;
  for (const std::string& line : Lines(*table)) {
    if (line.rfind("# ", 0) == 0) {
      ++block;
      continue;
    }
    if (line.empty()) continue;
    std::vector<std::string> fields = absl::StrSplit(line, '\t');
    (block == 0 ? histogram_rows : trace_rows).push_back(fields);
  }
  ASSERT_EQ(histogram_rows.size(), 10u);
  for (std::size_t bin = 0; bin < 10; ++bin) {
    EXPECT_EQ(std::stoll(histogram_rows[bin][2]), before[bin]) << bin;
    EXPECT_EQ(std::stoll(histogram_rows[bin][3]), after[bin]) << bin;
  }
  absl::StatusOr<std::string> trace_text = formats::ReadFileBytes(trace);
  ASSERT_TRUE(trace_text.ok());
  std::vector<testing::JsonValue> progress;
  for (const std::string& line : Lines(*trace_text)) {
    std::optional<testing::JsonValue> event = ParseJson(line);
    ASSERT_TRUE(event.has_value()) << line;
    if (event->Find("event")->string == "progress") progress.push_back(*event);
  }
  ASSERT_FALSE(progress.empty());
  ASSERT_EQ(trace_rows.size(), progress.size());
  for (std::size_t i = 0; i < progress.size(); ++i) {
    EXPECT_EQ(trace_rows[i][1], progress[i].Find("phase")->string);
    EXPECT_EQ(std::stod(trace_rows[i][4]), progress[i].Find("q_mean")->number);
  }

  const std::string png = TempPath("report.picture");
  ExpectSuccess(RunGetme({"report", source, output, "-o", png, "--format", "png"}));
  absl::StatusOr<std::string> png_bytes = formats::ReadFileBytes(png);
  ASSERT_TRUE(png_bytes.ok());
  EXPECT_EQ(png_bytes->substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
}

TEST(CliReport, BadTraceLineIsNamed) {
  const std::string source = GroupedHybrid("hybrid-groups.msh");
  RunResult usage = RunGetme({"report", source, source, "--format", "pdf"});
  EXPECT_EQ(usage.exit_status, 2);
  EXPECT_NE(usage.err.find("the picture format is svg or png, got 'pdf'"), std::string::npos)
      << usage.err;
  const std::string trace = TempPath("bad.jsonl");
  ASSERT_TRUE(formats::WriteFileAtomically(trace, "{\"event\":\"progress\"}\n").ok());
  RunResult run = RunGetme({"report", source, source, "--trace", trace});
  EXPECT_EQ(run.exit_status, 1);
  EXPECT_NE(run.err.find("bad.jsonl:1: progress event: no field 'phase'"), std::string::npos)
      << run.err;
  ASSERT_TRUE(formats::WriteFileAtomically(trace, "\nnot json\n").ok());
  run = RunGetme({"report", source, source, "--trace", trace});
  EXPECT_EQ(run.exit_status, 1);
  EXPECT_NE(run.err.find("bad.jsonl:2: not a JSON object"), std::string::npos) << run.err;
}

}  // namespace
}  // namespace getme::cli
