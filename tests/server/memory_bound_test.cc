// The real getme-server process over many rounds of jobs: its resident memory stays bounded.
// Labelled slow (about 20 s).
#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <string>
#include <thread>
#include <vector>

#include "absl/strings/str_cat.h"
#include "absl/time/clock.h"
#include "gtest/gtest.h"
#include "remote/smoother_client.h"
#include "server_process.h"
#include "server_test_support.h"

namespace getme::server::testing {
namespace {

remote::SmoothJobOptions QuickJob() {
  remote::SmoothJobOptions job;
  job.parameters.set_method(v1::METHOD_SIMULTANEOUS);
  return job;
}

// Rounds of concurrent jobs; the resident memory of the last rounds stays near that of the first
// two (which include the allocator's and gRPC's one-time growth). A job whose meshes leaked would
// add more than its upload size (the job holds the topology, the engine mesh and the result), so
// the bound is one upload per job run after the first two rounds; the noise measured between
// rounds is about +-15 MB (MALLOC_ARENA_MAX=2 keeps glibc from spreading it over more arenas),
// well below the 40 MB bound.
TEST(MemoryBoundTest, ResidentMemoryStaysBoundedOverRoundsOfJobs) {
  const std::string log =
      absl::StrCat(::testing::TempDir(), "/getme-server-rss-", getpid(), ".log");
  ServerProcess server = SpawnServer(
      log, {"--workers=2", "--max_queued_jobs=16", "--result_ttl=200ms"}, {"MALLOC_ARENA_MAX=2"});
  ASSERT_GT(server.pid, 0);
  const int port = WaitForPort(log);
  ASSERT_GT(port, 0) << ReadFile(log);
  remote::SmootherClient client(
      remote::SmootherClient::CreateChannel(absl::StrCat("127.0.0.1:", port)));
  const v1::Mesh wire = ToWire(TetBlock(26, 0.3));
  constexpr int kRounds = 8;
  constexpr int kClients = 4;
  std::vector<std::int64_t> rss;
  int completed = 0;
  for (int round = 0; round < kRounds; ++round) {
    std::atomic<int> ok{0};
    std::vector<std::thread> clients;
    for (int c = 0; c < kClients; ++c) {
      clients.emplace_back([&] {
        absl::StatusOr<remote::RemoteSmoothResult> result = client.Smooth(wire, QuickJob(), {});
        EXPECT_TRUE(result.ok()) << result.status();
        if (result.ok()) ++ok;
      });
    }
    for (std::thread& thread : clients) thread.join();
    completed += ok.load();
    absl::SleepFor(absl::Milliseconds(500));  // past twice the TTL: the records are gone too
    rss.push_back(ResidentKiB(server.pid));
  }
  kill(server.pid, SIGTERM);
  EXPECT_EQ(WaitForExit(server.pid, absl::Seconds(30)), 0);
  EXPECT_EQ(completed, kRounds * kClients);
  const std::int64_t upload_kib = static_cast<std::int64_t>(wire.ByteSizeLong() >> 10);
  std::printf("RSS after each round (KiB):");
  for (std::int64_t value : rss) std::printf(" %lld", static_cast<long long>(value));
  std::printf("; %d jobs of %lld KiB uploads\n", completed, static_cast<long long>(upload_kib));
  const std::int64_t warm = std::max(rss[0], rss[1]);
  const std::int64_t last = *std::max_element(rss.end() - 3, rss.end());
  EXPECT_LT(last - warm, (kRounds - 2) * kClients * upload_kib)
      << "RSS grew by " << last - warm << " KiB";
  std::remove(log.c_str());
}

}  // namespace
}  // namespace getme::server::testing
