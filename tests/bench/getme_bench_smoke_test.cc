#include <fcntl.h>
#include <gtest/gtest.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "getme/mesh/mesh_quality.h"
#include "getme/meshgen/hybrid_block.h"
#include "getme/parallel/thread_pool.h"
#include "nlohmann/json.hpp"

extern char** environ;

namespace getme {
namespace {

using nlohmann::json;

// The same mesh as the --generate spec below, built here so the driver's counts and initial
// quality can be checked against the engine directly.
constexpr char kGenerator[] = "hybrid --size 4 --seed 3";
Mesh ReferenceMesh() { return *meshgen::HybridBlock(4, 4, 4, 0.3, 3); }

std::string ReadFile(const std::filesystem::path& path) {
  std::ifstream stream(path);
  std::ostringstream contents;
  contents << stream.rdbuf();
  return contents.str();
}

std::filesystem::path FreshDirectory(const std::string& name) {
  const std::filesystem::path dir = std::filesystem::path(::testing::TempDir()) /
                                    ("getme_bench_" + name + "_" + std::to_string(getpid()));
  std::filesystem::remove_all(dir);
  return dir;
}

// Runs getme-bench with `args`; returns its exit status, stdout in `out`.
int RunBench(const std::vector<std::string>& args, std::string& out) {
  const std::string binary = std::string(GETME_BINARY_DIR) + "/bin/getme-bench";
  const std::string out_path = FreshDirectory("stdout").string();
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, out_path.c_str(),
                                   O_WRONLY | O_CREAT | O_TRUNC, 0644);
  std::vector<std::string> argv_strings = {binary};
  argv_strings.insert(argv_strings.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& arg : argv_strings) argv.push_back(arg.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  if (posix_spawn(&pid, binary.c_str(), &actions, nullptr, argv.data(), environ) != 0) {
    posix_spawn_file_actions_destroy(&actions);
    ADD_FAILURE() << "cannot run " << binary;
    return -1;
  }
  posix_spawn_file_actions_destroy(&actions);
  int status = 0;
  waitpid(pid, &status, 0);
  out = ReadFile(out_path);
  std::filesystem::remove(out_path);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

std::vector<json> ReadJsonLines(const std::filesystem::path& path) {
  std::vector<json> lines;
  std::istringstream stream(ReadFile(path));
  std::string line;
  while (std::getline(stream, line)) lines.push_back(json::parse(line));  // throws if malformed
  return lines;
}

// What the driver derives from a trace, recomputed from the trace file itself.
json FirstTimeReaching(const std::vector<json>& trace, double q_mean) {
  for (const json& event : trace) {
    if (event["event"] == "progress" && event["q_mean"].get<double>() >= q_mean) {
      return event["elapsed_seconds"];
    }
  }
  return nullptr;
}

TEST(GetmeBenchSmoke, WritesMeasurementJsonAndMatchingTrace) {
  const std::filesystem::path dir = FreshDirectory("run");
  std::string out;
  ASSERT_EQ(RunBench({"--generate", kGenerator, "--name", "tiny", "--methods", "getme", "--repeats",
                      "2", "--target-q-mean", "0.75", "--out", dir.string()},
                     out),
            0);
  EXPECT_NE(out.find("| tiny |"), std::string::npos) << out;

  const json measurement = json::parse(ReadFile(dir / "tiny.getme.t1.json"));
  const Mesh reference = ReferenceMesh();
  ThreadPool pool(1);
  const MeshQuality initial = EvaluateMeshQuality(reference, pool);
  EXPECT_EQ(measurement["mesh"], "tiny");
  EXPECT_EQ(measurement["method"], "getme");
  EXPECT_EQ(measurement["mode"], "in-process");
  EXPECT_EQ(measurement["threads"], 1);
  EXPECT_EQ(measurement["repeats"], 2);
  EXPECT_EQ(measurement["runs"].size(), 2u);
  EXPECT_TRUE(measurement["repeats_agree"].get<bool>());
  EXPECT_EQ(measurement["elements"], reference.element_count());
  EXPECT_EQ(measurement["nodes"], reference.node_count());

  const json& result = measurement["result"];
  EXPECT_EQ(result["threads"], 1);
  EXPECT_DOUBLE_EQ(result["q_min_before"].get<double>(), initial.q_min);
  EXPECT_DOUBLE_EQ(result["q_mean_before"].get<double>(), initial.q_mean);
  EXPECT_GT(result["iterations_simultaneous"].get<int>(), 0);
  EXPECT_GT(result["iterations_sequential"].get<int>(), 0);
  EXPECT_GT(result["q_mean"].get<double>(), initial.q_mean);
  EXPECT_GT(result["q_min"].get<double>(), initial.q_min);

  for (const char* field : {"wall_seconds", "engine_seconds", "seconds_to_99_percent_gain",
                            "seconds_to_target", "peak_rss_bytes"}) {
    const json& spread = measurement[field];
    ASSERT_TRUE(spread.is_object()) << field;
    EXPECT_LE(spread["min"].get<double>(), spread["median"].get<double>()) << field;
    EXPECT_LE(spread["median"].get<double>(), spread["max"].get<double>()) << field;
  }
  EXPECT_GE(measurement["wall_seconds"]["min"].get<double>(),
            measurement["engine_seconds"]["min"].get<double>());
  // The mesh alone is ~10 kB; a process that reports less than 1 MB measured nothing.
  EXPECT_GT(measurement["peak_rss_bytes"]["min"].get<double>(), 1e6);

  const std::vector<json> trace = ReadJsonLines(dir / measurement["trace"].get<std::string>());
  ASSERT_GE(trace.size(), 3u);
  EXPECT_EQ(trace.front()["event"], "progress");
  const json& last_progress = trace[trace.size() - 2];
  const json& result_line = trace.back();
  EXPECT_EQ(last_progress["event"], "progress");
  EXPECT_TRUE(last_progress["phase_done"].get<bool>());
  EXPECT_EQ(result_line["event"], "result");
  EXPECT_EQ(last_progress["q_mean"].get<double>(), result_line["q_mean"].get<double>());
  EXPECT_EQ(result_line["q_mean"].get<double>(), result["q_mean"].get<double>());

  // The trace is the median repeat's (one of two: the lower), and its derived times match it.
  const double before = result["q_mean_before"].get<double>();
  const double gain = result["q_mean"].get<double>() - before;
  const json& runs = measurement["runs"];
  const std::size_t median = runs[0]["wall_seconds"] <= runs[1]["wall_seconds"] ? 0 : 1;
  EXPECT_EQ(runs[median]["seconds_to_99_percent_gain"],
            FirstTimeReaching(trace, before + 0.99 * gain));
  EXPECT_EQ(runs[median]["seconds_to_target"], FirstTimeReaching(trace, 0.75));
  EXPECT_EQ(runs[median]["progress_events"], trace.size() - 1);
  std::filesystem::remove_all(dir);
}

TEST(GetmeBenchSmoke, UnreachedTargetIsNull) {
  const std::filesystem::path dir = FreshDirectory("unreached");
  std::string out;
  ASSERT_EQ(RunBench({"--generate", kGenerator, "--name", "tiny", "--methods", "smart-laplace",
                      "--repeats", "1", "--target-q-mean", "0.999", "--out", dir.string()},
                     out),
            0);
  const json measurement = json::parse(ReadFile(dir / "tiny.smart-laplace.t1.json"));
  EXPECT_TRUE(measurement["seconds_to_target"].is_null());
  EXPECT_TRUE(measurement["runs"][0]["seconds_to_target"].is_null());
  EXPECT_TRUE(measurement["seconds_to_99_percent_gain"].is_object());
  std::filesystem::remove_all(dir);
}

// --kernel-lanes 2 runs the reference passes; the default runs the widest this machine has. The
// JSON records the width each used, and the result is the same bits either way.
TEST(GetmeBenchSmoke, KernelLanesAreRecordedAndDoNotChangeTheResult) {
  const std::filesystem::path reference_dir = FreshDirectory("lanes2");
  const std::filesystem::path widest_dir = FreshDirectory("lanes_widest");
  std::string out;
  ASSERT_EQ(RunBench({"--generate", kGenerator, "--name", "tiny", "--methods", "getme", "--repeats",
                      "1", "--kernel-lanes", "2", "--out", reference_dir.string()},
                     out),
            0);
  ASSERT_EQ(RunBench({"--generate", kGenerator, "--name", "tiny", "--methods", "getme", "--repeats",
                      "1", "--out", widest_dir.string()},
                     out),
            0);
  const json reference = json::parse(ReadFile(reference_dir / "tiny.getme.t1.json"));
  const json widest = json::parse(ReadFile(widest_dir / "tiny.getme.t1.json"));
  EXPECT_EQ(reference["kernel_lanes"], 2);
  EXPECT_EQ(reference["smoothing_options"], "--kernel-lanes 2");
  EXPECT_TRUE(widest["kernel_lanes"] == 2 || widest["kernel_lanes"] == 4 ||
              widest["kernel_lanes"] == 8)
      << widest["kernel_lanes"];
  EXPECT_EQ(widest["result"]["q_min"], reference["result"]["q_min"]);
  EXPECT_EQ(widest["result"]["q_mean"], reference["result"]["q_mean"]);
  std::filesystem::remove_all(reference_dir);
  std::filesystem::remove_all(widest_dir);
}

TEST(GetmeBenchSmoke, KernelLanesOtherThanTwoFourOrEightAreRefused) {
  std::string out;
  for (const char* lanes : {"3", "16", "0", "four"}) {
    EXPECT_EQ(RunBench({"--generate", kGenerator, "--kernel-lanes", lanes}, out), 2) << lanes;
  }
}

#ifdef GETME_BENCH_WITH_SERVICE
// Through a getme-server the driver starts: the same result as in-process (the engine is
// deterministic and element order does not matter), and the overhead table is printed.
TEST(GetmeBenchSmoke, ServiceRunAgreesWithInProcess) {
  const std::filesystem::path dir = FreshDirectory("service");
  std::string out;
  ASSERT_EQ(RunBench({"--generate", kGenerator, "--name", "tiny", "--methods", "simultaneous",
                      "--repeats", "1", "--service", "--out", dir.string()},
                     out),
            0);
  const json local = json::parse(ReadFile(dir / "tiny.simultaneous.t1.json"));
  const json remote = json::parse(ReadFile(dir / "tiny.simultaneous.t1.service.json"));
  EXPECT_EQ(remote["mode"], "service");
  EXPECT_EQ(remote["result"]["q_mean"], local["result"]["q_mean"]);
  EXPECT_EQ(remote["result"]["q_min"], local["result"]["q_min"]);
  EXPECT_EQ(remote["result"]["iterations_simultaneous"],
            local["result"]["iterations_simultaneous"]);
  EXPECT_GT(remote["server_peak_rss_bytes"]["median"].get<double>(), 1e6);
  EXPECT_NE(out.find("| in-process wall s | service wall s | overhead |"), std::string::npos)
      << out;
  const std::vector<json> trace = ReadJsonLines(dir / remote["trace"].get<std::string>());
  EXPECT_EQ(trace[trace.size() - 2]["q_mean"], remote["result"]["q_mean"]);
  std::filesystem::remove_all(dir);
}
#endif

}  // namespace
}  // namespace getme
