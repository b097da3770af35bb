// The `getme` executable against an in-process server: `smooth --server` writes the same file as
// the local mode, --json lines keep their order and keys, errors print the server's code and
// message, and `getme jobs` lists, cancels, watches and fetches detached jobs.

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <set>
#include <sstream>
#include <thread>

#include "absl/strings/match.h"
#include "absl/strings/str_split.h"
#include "formats/grid_mesh.h"
#include "formats/vtk_writer.h"
#include "getme/meshgen/layered_hex_block.h"
#include "getme_wire/engine_mesh.h"
#include "getme_wire/params.h"
#include "json_test_parser.h"
#include "remote/grid_upload.h"
#include "remote/smoother_client.h"
#include "run_getme.h"
#include "test_meshes.h"
#include "test_server.h"

namespace getme::remote {
namespace {

using cli::testing::JsonValue;
using cli::testing::Lines;
using cli::testing::ParseJson;
using cli::testing::RunGetme;
using cli::testing::RunResult;
using cli::testing::TempPath;
using wire::ToWireMesh;
using wire::ToWireParameters;

const std::string kHybrid = std::string(GETME_TEST_DATA) + "/hybrid-example.vtk";
const std::string kHexBlock =
    std::string(GETME_SHARED_MESHES) + "/mesquite/1000hex-block-internal-bias.vtk";

std::string ReadFile(const std::string& path) {
  std::ifstream stream(path, std::ios::binary);
  std::ostringstream contents;
  contents << stream.rdbuf();
  return contents.str();
}

std::vector<JsonValue> JsonLines(const std::string& out) {
  std::vector<JsonValue> values;
  for (const std::string& line : Lines(out)) {
    std::optional<JsonValue> value = ParseJson(line);
    EXPECT_TRUE(value.has_value()) << "not JSON: " << line;
    if (value) values.push_back(*std::move(value));
  }
  return values;
}

std::vector<std::string> Keys(const JsonValue& object) {
  std::vector<std::string> keys;
  for (const auto& [key, value] : object.object) keys.push_back(key);
  return keys;
}

class RemoteCliTest : public ::testing::Test {
 protected:
  void SetUp() override {
    server_ = testing::StartTestServer(/*workers=*/1);
    ASSERT_NE(server_, nullptr);
    target_ = testing::TargetOf(*server_);
  }
  void TearDown() override {
    if (server_) server_->Shutdown(absl::Seconds(1));
  }

  // `getme smooth input output options...` locally into local_out, then with --server into
  // remote_out.
  struct LocalAndRemote {
    RunResult local;
    RunResult remote;
  };
  LocalAndRemote SmoothBothWays(const std::string& input, const std::string& local_out,
                                const std::string& remote_out,
                                const std::vector<std::string>& options) const {
    std::vector<std::string> local_args = {"smooth", input, local_out};
    local_args.insert(local_args.end(), options.begin(), options.end());
    std::vector<std::string> remote_args = {"smooth", input, remote_out, "--server", target_};
    remote_args.insert(remote_args.end(), options.begin(), options.end());
    return {RunGetme(local_args), RunGetme(remote_args)};
  }

  std::unique_ptr<server::SmootherServer> server_;
  std::string target_;
};

// A Gmsh file with named groups (written by gmsh): --fix-physical goes to the server as fixed
// nodes, and the written .msh (surfaces, groups, $ElementData quality) is byte for byte the
// local one.
TEST_F(RemoteCliTest, RemoteSmoothOfGmshFileWithGroupsMatchesLocal) {
  const std::string input = std::string(GETME_GROUPED_HYBRID_DIR) + "/hybrid-groups.msh";
  const std::string local_out = TempPath("local.msh");
  const std::string remote_out = TempPath("remote.msh");
  const auto [local, remote] = SmoothBothWays(
      input, local_out, remote_out, {"--free-boundary", "--fix-physical", "inlet", "--quiet"});
  ASSERT_EQ(local.exit_status, 0) << local.err;
  ASSERT_EQ(remote.exit_status, 0) << remote.err;
  const std::string local_bytes = ReadFile(local_out);
  EXPECT_GT(local_bytes.size(), 1000u);
  EXPECT_TRUE(local_bytes == ReadFile(remote_out)) << "remote and local .msh differ";
  EXPECT_NE(local_bytes, ReadFile(input));
}

// A sliding boundary on a file with physical groups (inlet, walls): the client sends the tagged
// faces (mesh.proto's group fields), so the server keeps the same surface groups as the local run
// and writes the same file. Without them it would see one group and slide inlet nodes onto the
// walls' side of their common edges.
TEST_F(RemoteCliTest, SlidingOnAFileWithPhysicalGroupsKeepsTheGroupsRemotely) {
  const std::string input = std::string(GETME_GROUPED_HYBRID_DIR) + "/hybrid-groups.msh";
  const std::string local_out = TempPath("local.msh");
  const std::string remote_out = TempPath("remote.msh");
  const auto [local, remote] = SmoothBothWays(
      input, local_out, remote_out, {"--boundary", "slide", "--json", "--quiet", "--threads", "1"});
  ASSERT_EQ(local.exit_status, 0) << local.err;
  ASSERT_EQ(remote.exit_status, 0) << remote.err;
  const JsonValue local_result = JsonLines(local.out).back();
  const JsonValue remote_result = JsonLines(remote.out).back();
  const JsonValue* local_slide = local_result.Find("boundary_slide");
  const JsonValue* remote_slide = remote_result.Find("boundary_slide");
  ASSERT_NE(local_slide, nullptr) << local.out;
  ASSERT_NE(remote_slide, nullptr) << remote.out;
  EXPECT_EQ(local_slide->Find("surface_groups")->number, 3);  // inlet, walls, and group 0
  EXPECT_EQ(remote_slide->Find("surface_groups")->number, 3);
  EXPECT_EQ(remote_slide->Find("feature_edges")->number,
            local_slide->Find("feature_edges")->number);
  EXPECT_GT(remote_slide->Find("slid_nodes")->number, 0);
  EXPECT_TRUE(ReadFile(local_out) == ReadFile(remote_out)) << "remote and local .msh differ";
}

// The client converts, the wire does not change (issue 17): a Gmsh mesh with named groups,
// converted to each format of issue 17, smooths through the service with a sliding boundary to
// what the local run writes, with the same surface groups. Both outputs are compared as the VTK
// files `getme convert` makes of them (a CGNS or Exodus file's bytes also hold HDF5 and netCDF
// bookkeeping); an OpenFOAM input is a case directory, and so is its output.
TEST_F(RemoteCliTest, EveryFileFormatSmoothsRemotelyAsLocally) {
  const std::string source = std::string(GETME_GROUPED_HYBRID_DIR) + "/hybrid-groups.msh";
  struct Variant {
    std::string name;  // the input's file name; no extension: an OpenFOAM case
    std::vector<std::string> convert_options;
  };
  const std::vector<Variant> variants = {
      {"in.su2", {}}, {"in.cgns", {}}, {"in.exo", {}}, {"in-case", {"--format", "openfoam"}}};
  for (const Variant& variant : variants) {
    SCOPED_TRACE(variant.name);
    const std::string input = TempPath(variant.name);
    std::vector<std::string> convert = {"convert", source, input};
    convert.insert(convert.end(), variant.convert_options.begin(), variant.convert_options.end());
    const RunResult converted = RunGetme(convert);
    ASSERT_EQ(converted.exit_status, 0) << converted.err;
    const std::string extension =
        variant.name.find('.') == std::string::npos ? "" : variant.name.substr(2);
    const std::string local_out = TempPath("local" + extension);
    const std::string remote_out = TempPath("remote" + extension);
    // The output format as the input's: an OpenFOAM output needs --format (TempPath's dots).
    std::vector<std::string> options = {"--boundary", "slide",     "--json",
                                        "--quiet",    "--threads", "1"};
    options.insert(options.end(), variant.convert_options.begin(), variant.convert_options.end());
    const auto [local, remote] = SmoothBothWays(input, local_out, remote_out, options);
    ASSERT_EQ(local.exit_status, 0) << local.err;
    ASSERT_EQ(remote.exit_status, 0) << remote.err;
    const JsonValue local_result = JsonLines(local.out).back();
    const JsonValue remote_result = JsonLines(remote.out).back();
    const JsonValue* local_slide = local_result.Find("boundary_slide");
    const JsonValue* remote_slide = remote_result.Find("boundary_slide");
    ASSERT_NE(local_slide, nullptr) << local.out;
    ASSERT_NE(remote_slide, nullptr) << remote.out;
    EXPECT_EQ(remote_slide->Find("surface_groups")->number,
              local_slide->Find("surface_groups")->number);
    EXPECT_GT(remote_slide->Find("slid_nodes")->number, 0);
    const std::string local_vtk = TempPath("local-" + variant.name + ".vtk");
    const std::string remote_vtk = TempPath("remote-" + variant.name + ".vtk");
    ASSERT_EQ(RunGetme({"convert", local_out, local_vtk}).exit_status, 0);
    ASSERT_EQ(RunGetme({"convert", remote_out, remote_vtk}).exit_status, 0);
    const std::string local_bytes = ReadFile(local_vtk);
    EXPECT_GT(local_bytes.size(), 1000u);
    EXPECT_TRUE(local_bytes == ReadFile(remote_vtk)) << "remote and local results differ";
  }
}

TEST_F(RemoteCliTest, RemoteSmoothWritesTheSameFileAsLocal) {
  for (const std::string& input : {kHexBlock, kHybrid}) {
    const std::string local_out = TempPath("local.vtk");
    const std::string remote_out = TempPath("remote.vtk");
    const RunResult local = RunGetme({"smooth", input, local_out, "--quiet", "--threads", "1"});
    ASSERT_EQ(local.exit_status, 0) << local.err;
    const RunResult remote = RunGetme({"smooth", input, remote_out, "--server", target_});
    ASSERT_EQ(remote.exit_status, 0) << remote.err;
    const std::string local_file = ReadFile(local_out);
    ASSERT_FALSE(local_file.empty());
    EXPECT_TRUE(local_file == ReadFile(remote_out))
        << input << ": the remote result file differs from the local one";
    // The summary table is printed as in local mode.
    EXPECT_NE(remote.out.find("q_mean"), std::string::npos) << remote.out;
  }
}

TEST_F(RemoteCliTest, JsonEventsInOrderAndTheSameResultKeys) {
  const RunResult local =
      RunGetme({"smooth", kHybrid, TempPath("local.vtk"), "--json", "--threads", "1"});
  ASSERT_EQ(local.exit_status, 0) << local.err;
  const RunResult remote =
      RunGetme({"smooth", kHybrid, TempPath("remote.vtk"), "--json", "--server", target_});
  ASSERT_EQ(remote.exit_status, 0) << remote.err;
  const std::vector<JsonValue> local_lines = JsonLines(local.out);
  const std::vector<JsonValue> remote_lines = JsonLines(remote.out);
  ASSERT_GE(remote_lines.size(), 3u);
  // The server streams every engine event (unthrottled test server): the same lines but time.
  ASSERT_EQ(remote_lines.size(), local_lines.size());
  for (std::size_t i = 0; i + 1 < remote_lines.size(); ++i) {
    EXPECT_EQ(remote_lines[i].Find("event")->string, "progress") << "line " << i;
    EXPECT_EQ(Keys(remote_lines[i]), Keys(local_lines[i])) << "line " << i;
    for (const char* key : {"phase", "iteration", "q_min", "q_mean", "phase_done"}) {
      const JsonValue* l = local_lines[i].Find(key);
      const JsonValue* r = remote_lines[i].Find(key);
      ASSERT_TRUE(l != nullptr && r != nullptr) << key;
      // The wire numbers elements by type, the file does not; the engine's canonical order
      // makes that irrelevant: bit-identical.
      EXPECT_EQ(r->number, l->number) << "line " << i << " " << key;
      EXPECT_EQ(r->string, l->string) << "line " << i << " " << key;
      EXPECT_EQ(r->boolean, l->boolean) << "line " << i << " " << key;
    }
  }
  const JsonValue& result = remote_lines.back();
  EXPECT_EQ(result.Find("event")->string, "result");
  EXPECT_EQ(Keys(result), Keys(local_lines.back()));
  EXPECT_EQ(result.Find("q_min")->number, local_lines.back().Find("q_min")->number);
  EXPECT_EQ(result.Find("q_mean")->number, local_lines.back().Find("q_mean")->number);
  EXPECT_GT(result.Find("q_mean")->number, result.Find("q_mean_before")->number);
}

TEST_F(RemoteCliTest, RemoteQualityMatchesLocal) {
  const RunResult local = RunGetme({"quality", kHybrid, "--json"});
  const RunResult remote = RunGetme({"quality", kHybrid, "--json", "--server", target_});
  ASSERT_EQ(local.exit_status, 0) << local.err;
  ASSERT_EQ(remote.exit_status, 0) << remote.err;
  const std::optional<JsonValue> l = ParseJson(Lines(local.out).at(0));
  const std::optional<JsonValue> r = ParseJson(Lines(remote.out).at(0));
  ASSERT_TRUE(l && r) << remote.out;
  EXPECT_EQ(Keys(*r), Keys(*l));
  for (const auto& [key, value] : l->object) {
    const JsonValue* other = r->Find(key);
    ASSERT_NE(other, nullptr) << key;
    if (key == "by_type" || key == "histogram" || key == "first_invalid") {
      EXPECT_EQ(r->Find(key)->array.size(), value.array.size()) << key;
    } else {
      EXPECT_EQ(other->number, value.number) << key;
      EXPECT_EQ(other->string, value.string) << key;
    }
  }
  const std::vector<std::string> local_lines = absl::StrSplit(local.out, ",\"by_type\"");
  const std::vector<std::string> remote_lines = absl::StrSplit(remote.out, ",\"by_type\"");
  ASSERT_EQ(remote_lines.size(), 2u);
  EXPECT_EQ(remote_lines[1], local_lines[1]) << "per-type statistics and histogram differ";
}

TEST(RemoteCliErrors, UnreachableServerIsUnavailable) {
  const RunResult run =
      RunGetme({"smooth", kHybrid, TempPath("out.vtk"), "--server", "127.0.0.1:1"});
  EXPECT_EQ(run.exit_status, 1);
  EXPECT_TRUE(absl::StrContains(run.err, "\ngetme: UNAVAILABLE: failed to connect")) << run.err;
  const RunResult json = RunGetme({"jobs", "list", "--server", "127.0.0.1:1", "--json"});
  EXPECT_EQ(json.exit_status, 1);
  std::optional<JsonValue> error = ParseJson(Lines(json.out).at(0));
  ASSERT_TRUE(error.has_value()) << json.out;
  EXPECT_EQ(error->Find("code")->string, "UNAVAILABLE");
}

TEST_F(RemoteCliTest, InvalidMeshPrintsTheServersInvalidArgument) {
  // A tetrahedron listing node 1 twice: not checked on the client, refused by the server.
  const std::string input = TempPath("bad.vtk");
  std::ofstream(input) << "# vtk DataFile Version 3.0\nbad\nASCII\nDATASET UNSTRUCTURED_GRID\n"
                          "POINTS 4 double\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n"
                          "CELLS 1 5\n4 0 1 1 3\nCELL_TYPES 1\n10\n";
  const std::string output = TempPath("out.vtk");
  const RunResult run = RunGetme({"smooth", input, output, "--server", target_});
  EXPECT_EQ(run.exit_status, 1);
  EXPECT_TRUE(absl::StrContains(run.err, "getme: INVALID_ARGUMENT: ")) << run.err;
  EXPECT_FALSE(std::ifstream(output).good()) << "no output on failure";
}

TEST_F(RemoteCliTest, DetachListCancelQueuedJob) {
  // One worker busy with a long job keeps the detached one queued until it is cancelled.
  SmootherClient client(SmootherClient::CreateChannel(target_));
  SmoothJobOptions long_job;
  long_job.parameters = ToWireParameters(SmoothingParams());
  absl::StatusOr<v1::Job> blocker =
      client.SubmitJob(ToWireMesh(testing::DistortedHexBlock(40, 0.2)), long_job);
  ASSERT_TRUE(blocker.ok()) << blocker.status();

  const RunResult detached = RunGetme({"smooth", kHybrid, "--server", target_, "--detach"});
  ASSERT_EQ(detached.exit_status, 0) << detached.err;
  const std::string job_id = Lines(detached.out).at(0);
  ASSERT_FALSE(job_id.empty());

  const RunResult list = RunGetme({"jobs", "list", "--server", target_});
  ASSERT_EQ(list.exit_status, 0) << list.err;
  EXPECT_TRUE(absl::StrContains(list.out, job_id)) << list.out;
  EXPECT_TRUE(absl::StrContains(list.out, blocker->job_id())) << list.out;

  const RunResult cancel = RunGetme({"jobs", "cancel", job_id, "--server", target_, "--json"});
  ASSERT_EQ(cancel.exit_status, 0) << cancel.err;
  absl::StatusOr<v1::Job> job = client.GetJob(job_id);
  for (int i = 0; i < 100 && job.ok() && job->state() != v1::JOB_STATE_CANCELLED; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    job = client.GetJob(job_id);
  }
  ASSERT_TRUE(job.ok()) << job.status();
  EXPECT_EQ(job->state(), v1::JOB_STATE_CANCELLED);
  // Watching a cancelled job ends at once and fails.
  const RunResult watch = RunGetme({"jobs", "watch", job_id, "--server", target_});
  EXPECT_EQ(watch.exit_status, 1) << watch.err;
  EXPECT_TRUE(absl::StrContains(watch.err, "CANCELLED")) << watch.err;

  ASSERT_TRUE(client.CancelJob(blocker->job_id()).ok());
  const RunResult unknown = RunGetme({"jobs", "cancel", "no-such-job", "--server", target_});
  EXPECT_EQ(unknown.exit_status, 1);
  EXPECT_TRUE(absl::StartsWith(unknown.err, "getme: NOT_FOUND: ")) << unknown.err;
}

TEST_F(RemoteCliTest, DetachWatchFetchWritesTheLocalResult) {
  const std::string local_out = TempPath("local.vtk");
  ASSERT_EQ(RunGetme({"smooth", kHybrid, local_out, "--quiet", "--threads", "1"}).exit_status, 0);
  const RunResult detached = RunGetme({"smooth", kHybrid, "--server", target_, "--detach"});
  ASSERT_EQ(detached.exit_status, 0) << detached.err;
  const std::string job_id = Lines(detached.out).at(0);
  const RunResult watch = RunGetme({"jobs", "watch", job_id, "--server", target_, "--json"});
  ASSERT_EQ(watch.exit_status, 0) << watch.err;
  // The watch prints the progress events still to come, then the job's end. How many progress
  // events come depends on how far the job got before the watch attached (2,529 elements take
  // about 0.1 s: often none), so only their kind is fixed; the server tests check the stream of
  // a running job (tests/server/jobs_test.cc).
  const std::vector<JsonValue> events = JsonLines(watch.out);
  ASSERT_GE(events.size(), 1u) << watch.out;
  ASSERT_NE(events.back().Find("state"), nullptr) << watch.out;
  EXPECT_EQ(events.back().Find("state")->string, "SUCCEEDED");
  for (std::size_t i = 0; i + 1 < events.size(); ++i) {
    ASSERT_NE(events[i].Find("event"), nullptr) << watch.out;
    EXPECT_EQ(events[i].Find("event")->string, "progress") << "event " << i;
  }
  const std::string fetched = TempPath("fetched.vtk");
  const RunResult fetch =
      RunGetme({"jobs", "fetch", job_id, fetched, "--input", kHybrid, "--server", target_});
  ASSERT_EQ(fetch.exit_status, 0) << fetch.err;
  EXPECT_TRUE(ReadFile(fetched) == ReadFile(local_out)) << "fetched file differs from local";
}

// Whether two JSON values are the same, numbers bit for bit; `path` names the first difference.
bool SameJson(const JsonValue& a, const JsonValue& b, const std::string& path, std::string& diff) {
  if (a.kind != b.kind || a.boolean != b.boolean || a.number != b.number || a.string != b.string ||
      a.array.size() != b.array.size() || Keys(a) != Keys(b)) {
    diff = path;
    return false;
  }
  for (std::size_t i = 0; i < a.array.size(); ++i) {
    if (!SameJson(a.array[i], b.array[i], absl::StrCat(path, "[", i, "]"), diff)) return false;
  }
  for (std::size_t i = 0; i < a.object.size(); ++i) {
    const std::string member = absl::StrCat(path, ".", a.object[i].key);
    if (!SameJson(a.object[i].value, b.object[i].value, member, diff)) return false;
  }
  return true;
}

// The text summary from its boundary section to the timings: what a slide and kept layers did.
std::string BoundarySection(const std::string& summary) {
  const std::size_t begin = summary.find("\nboundary ");
  const std::size_t end = summary.find("\nseconds ");
  if (begin == std::string::npos || end == std::string::npos || end < begin) return "";
  return summary.substr(begin, end - begin);
}

// --boundary slide --keep-layers through the service (issue 15), on a hexahedral boundary-layer
// block (the one getme-meshgen hex-layers makes): the same file as the local run, and the same
// boundary, boundary_slide and layers in --json and the text summary; `jobs fetch` of a detached
// job, which knows nothing of the parameters, reports them from the result alone.
TEST_F(RemoteCliTest, SlidingBoundaryAndKeptLayersMatchLocal) {
  const std::string input = TempPath("hex-layers.vtk");
  absl::StatusOr<Mesh> block = meshgen::LayeredHexBlock(6, 6, 10, 0.01, 1.3, 0.3, 7);
  ASSERT_TRUE(block.ok()) << block.status();
  // Each interior column shifted sideways as a whole: an irregular wall grid for the slide to
  // even out (node (i, j, k) is i + 7 j + 49 k).
  for (int j = 1; j < 6; ++j) {
    for (int i = 1; i < 6; ++i) {
      for (int k = 0; k <= 10; ++k) {
        block->x()[i + 7 * j + 49 * k] += 0.2 * std::sin(7.0 * i + 3.0 * j);
        block->y()[i + 7 * j + 49 * k] += 0.2 * std::cos(5.0 * i + 11.0 * j);
      }
    }
  }
  ASSERT_TRUE(formats::WriteVtkFile(input, formats::GridFromMesh(*block, "hex layers")).ok());
  const std::vector<std::string> options = {"--boundary", "slide", "--keep-layers", "--threads",
                                            "1"};
  const auto smooth = [&](const std::string& output, std::vector<std::string> extra) {
    std::vector<std::string> args = {"smooth", input, output};
    args.insert(args.end(), options.begin(), options.end());
    args.insert(args.end(), extra.begin(), extra.end());
    return RunGetme(args);
  };
  const std::string local_out = TempPath("local.vtk");
  const std::string remote_out = TempPath("remote.vtk");
  const RunResult local = smooth(local_out, {"--json"});
  ASSERT_EQ(local.exit_status, 0) << local.err;
  const RunResult remote = smooth(remote_out, {"--json", "--server", target_});
  ASSERT_EQ(remote.exit_status, 0) << remote.err;
  EXPECT_TRUE(ReadFile(local_out) == ReadFile(remote_out)) << "remote and local files differ";

  const JsonValue local_result = JsonLines(local.out).back();
  const JsonValue remote_result = JsonLines(remote.out).back();
  EXPECT_EQ(Keys(remote_result), Keys(local_result));
  EXPECT_EQ(remote_result.Find("boundary")->string, "slide");
  const JsonValue* slide = remote_result.Find("boundary_slide");
  ASSERT_NE(slide, nullptr) << remote.out;
  EXPECT_GT(slide->Find("slid_nodes")->number, 0);
  EXPECT_EQ(slide->Find("feature_curves")->number, 12);  // a box's edges
  EXPECT_EQ(slide->Find("corners")->number, 8);
  const JsonValue* layers = remote_result.Find("layers");
  ASSERT_NE(layers, nullptr) << remote.out;
  EXPECT_EQ(layers->Find("columns")->number, 36);
  EXPECT_EQ(layers->Find("layers")->number, 10);
  EXPECT_LE(layers->Find("max_height_change")->number, 0.01);
  for (const char* key : {"boundary", "boundary_slide", "layers", "q_min", "q_mean", "phases"}) {
    std::string diff;
    const JsonValue* expected = local_result.Find(key);
    ASSERT_NE(expected, nullptr) << key;
    if (std::string(key) == "phases") {  // but their seconds
      ASSERT_EQ(remote_result.Find(key)->array.size(), expected->array.size());
      for (std::size_t i = 0; i < expected->array.size(); ++i) {
        EXPECT_EQ(remote_result.Find(key)->array[i].Find("phase")->string,
                  expected->array[i].Find("phase")->string);
        EXPECT_EQ(remote_result.Find(key)->array[i].Find("iterations")->number,
                  expected->array[i].Find("iterations")->number);
      }
      continue;
    }
    EXPECT_TRUE(SameJson(*remote_result.Find(key), *expected, key, diff)) << "differs at " << diff;
  }
  EXPECT_EQ(remote_result.Find("phases")->array.front().Find("phase")->string, "layers");

  // The text summary says the same.
  const RunResult local_text = smooth(TempPath("local-text.vtk"), {"--quiet"});
  const RunResult remote_text =
      smooth(TempPath("remote-text.vtk"), {"--quiet", "--server", target_});
  ASSERT_EQ(local_text.exit_status, 0) << local_text.err;
  ASSERT_EQ(remote_text.exit_status, 0) << remote_text.err;
  const std::string section = BoundarySection(local_text.out);
  EXPECT_TRUE(absl::StrContains(section, "boundary         slide: ")) << local_text.out;
  EXPECT_TRUE(absl::StrContains(section, "layers           kept: 36 columns")) << local_text.out;
  EXPECT_EQ(BoundarySection(remote_text.out), section) << remote_text.out;

  // A detached job, watched and fetched.
  std::vector<std::string> detach = {"smooth", input, "--server", target_, "--detach"};
  detach.insert(detach.end(), options.begin(), options.end());
  const RunResult detached = RunGetme(detach);
  ASSERT_EQ(detached.exit_status, 0) << detached.err;
  const std::string job_id = Lines(detached.out).at(0);
  ASSERT_EQ(RunGetme({"jobs", "watch", job_id, "--server", target_}).exit_status, 0);
  const std::string fetched = TempPath("fetched.vtk");
  const RunResult fetch =
      RunGetme({"jobs", "fetch", job_id, fetched, "--input", input, "--server", target_, "--json"});
  ASSERT_EQ(fetch.exit_status, 0) << fetch.err;
  EXPECT_TRUE(ReadFile(fetched) == ReadFile(local_out)) << "fetched file differs from local";
  const JsonValue fetched_result = JsonLines(fetch.out).back();
  EXPECT_EQ(fetched_result.Find("boundary")->string, "slide");
  for (const char* key : {"boundary_slide", "layers"}) {
    std::string diff;
    ASSERT_NE(fetched_result.Find(key), nullptr) << fetch.out;
    EXPECT_TRUE(SameJson(*fetched_result.Find(key), *local_result.Find(key), key, diff))
        << "differs at " << diff;
  }
}

}  // namespace
}  // namespace getme::remote
