// Several real getme-server processes sharing one real redis-server (--job_store, issue 18): any
// replica answers for any job, a killed replica loses nothing, and the cluster's queue limit holds.
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <iostream>
#include <memory>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "absl/strings/match.h"
#include "absl/strings/numbers.h"
#include "absl/strings/str_cat.h"
#include "absl/time/clock.h"
#include "auth_test_support.h"
#include "gtest/gtest.h"
#include "http_test_support.h"
#include "redis/redis_address.h"
#include "redis/redis_client.h"
#include "redis_server_process.h"
#include "redis_server_test.h"
#include "remote/smoother_client.h"
#include "run_getme.h"
#include "server_process.h"
#include "server_test_support.h"
#include "temp_files.h"
#include "test_certificates.h"

namespace getme::server::testing {
namespace {

using redis::testing::RedisServerProcess;

// Short enough that a killed replica's job restarts well within the test's patience (RunnerOf
// waits 30 s); long enough that a live replica's renewals (every third of it) survive a stall of
// a few seconds on a loaded machine, which would otherwise hand its job to another replica.
constexpr char kLease[] = "--job_lease=4s";

struct Replica {
  ServerProcess process;
  int port = 0;
  int http_port = 0;  // 0 unless started with --http_listen
  std::string address;
  std::unique_ptr<remote::SmootherClient> client;
};

class ReplicasTest : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!RedisServerProcess::Available()) GTEST_SKIP() << "no /usr/bin/redis-server";
    absl::StatusOr<std::unique_ptr<RedisServerProcess>> redis =
        RedisServerProcess::Start(RedisOptions());
    ASSERT_TRUE(redis.ok()) << redis.status();
    redis_ = *std::move(redis);
    absl::StatusOr<redis::RedisAddress> address = redis::ParseRedisUrl(StoreUrl());
    ASSERT_TRUE(address.ok()) << address.status();
    absl::StatusOr<std::unique_ptr<redis::RedisClient>> store =
        redis::RedisClient::Connect(*address);
    ASSERT_TRUE(store.ok()) << store.status();
    store_ = *std::move(store);
  }

  virtual RedisServerProcess::Options RedisOptions() const { return {}; }
  // What the replicas and the test's own client give as --job_store.
  virtual std::string StoreUrl() const { return redis_->url(); }

  void TearDown() override {
    if (HasFailure()) {
      // A failed call names only the replica's address: what the replica itself said tells why.
      for (std::size_t i = 0; i < replicas_.size(); ++i) {
        std::cerr << "---- replica " << i << " (pid " << replicas_[i].process.pid << ", "
                  << replicas_[i].address << ") log:\n"
                  << ReadFile(replicas_[i].process.log_path);
      }
    }
    for (Replica& replica : replicas_) {
      // Still our unreaped child: a replica the test already reaped may have a reused pid now.
      if (replica.process.pid > 0 && waitpid(replica.process.pid, nullptr, WNOHANG) == 0) {
        kill(replica.process.pid, SIGKILL);
        WaitForExit(replica.process.pid, absl::Seconds(10));
      }
      if (!HasFailure()) std::remove(replica.process.log_path.c_str());
    }
  }

  void StartReplicas(int count, const std::vector<std::string>& extra_flags = {}) {
    for (int i = 0; i < count; ++i) {
      // A name no other test of this process used: a stale log would name a dead server's port.
      static std::atomic<int> started{0};
      const std::string log = absl::StrCat(::testing::TempDir(), "/getme-replica-", getpid(), "-",
                                           started.fetch_add(1), ".log");
      std::vector<std::string> flags = {absl::StrCat("--job_store=", StoreUrl()), kLease,
                                        "--progress_interval=0"};
      flags.insert(flags.end(), extra_flags.begin(), extra_flags.end());
      Replica replica;
      replica.process = SpawnServer(log, flags);
      ASSERT_GT(replica.process.pid, 0);
      const int port = WaitForPort(log);
      ASSERT_GT(port, 0) << ReadFile(log);
      replica.port = port;
      for (const std::string& flag : flags) {
        if (flag.rfind("--http_listen=127.", 0) == 0) replica.http_port = WaitForHttpPort(log);
      }
      replica.address = absl::StrCat("127.0.0.1:", port);
      replica.client = std::make_unique<remote::SmootherClient>(
          remote::SmootherClient::CreateChannel(replica.address));
      replicas_.push_back(std::move(replica));
    }
  }

  // The replica whose log says it took `job_id` (attempt `attempt`); -1 if none within 30 s.
  int RunnerOf(const std::string& job_id, int attempt) const {
    const std::string line = absl::StrCat("job=", job_id, " phase=taken attempt=", attempt, " ");
    const absl::Time deadline = absl::Now() + absl::Seconds(30);
    while (absl::Now() < deadline) {
      for (std::size_t i = 0; i < replicas_.size(); ++i) {
        if (ReadFile(replicas_[i].process.log_path).find(line) != std::string::npos) {
          return static_cast<int>(i);
        }
      }
      absl::SleepFor(absl::Milliseconds(20));
    }
    return -1;
  }

  std::int64_t StoreInteger(std::initializer_list<std::string_view> command) const {
    absl::StatusOr<redis::RedisReply> reply = store_->Command(command);
    EXPECT_TRUE(reply.ok()) << reply.status();
    if (!reply.ok()) return -1;
    if (reply->type() == redis::RedisReply::Type::kInteger) return reply->integer();
    std::int64_t value = 0;
    if (!reply->is_nil()) {
      EXPECT_TRUE(absl::SimpleAtoi(reply->str(), &value)) << reply->str();
    }
    return value;
  }

  // No job holds a lease, waits in the queue, or counts against the byte limit.
  void ExpectStoreIdle() const {
    EXPECT_EQ(StoreInteger({"ZCARD", "getme:running"}), 0);
    EXPECT_EQ(StoreInteger({"LLEN", "getme:queue"}), 0);
    EXPECT_EQ(StoreInteger({"GET", "getme:held_bytes"}), 0);
  }

  std::unique_ptr<RedisServerProcess> redis_;
  std::unique_ptr<redis::RedisClient> store_;
  std::vector<Replica> replicas_;
};

// The same job through one in-process server without a store: the reference bits.
v1::Mesh SingleProcessResult(const v1::Mesh& mesh, const remote::SmoothJobOptions& job) {
  TestServer server = StartTestServer();
  remote::SmootherClient client(server.channel);
  absl::StatusOr<remote::RemoteSmoothResult> result = client.Smooth(mesh, job, {});
  EXPECT_TRUE(result.ok()) << result.status();
  return result.ok() ? result->mesh : v1::Mesh();
}

// Every event of a job as a watcher on `replica` receives them, to the end.
absl::StatusOr<std::vector<v1::ProgressEvent>> WatchToTheEnd(const Replica& replica,
                                                             const std::string& job_id) {
  std::vector<v1::ProgressEvent> events;
  absl::Status watched = replica.client->WatchJob(
      job_id, [&](const v1::ProgressEvent& event) { events.push_back(event); });
  if (!watched.ok()) return watched;
  return events;
}

void ExpectSameCoordinates(const v1::Mesh& expected, const v1::Mesh& actual) {
  ASSERT_EQ(expected.coordinates_size(), actual.coordinates_size());
  for (int i = 0; i < expected.coordinates_size(); ++i) {
    ASSERT_EQ(expected.coordinates(i), actual.coordinates(i)) << "coordinate " << i;
  }
}

TEST_F(ReplicasTest, SubmitOnAWatchOnBFromTheFirstEventFetchOnCGivesTheSingleProcessBits) {
  StartReplicas(3);
  const v1::Mesh mesh = ToWire(TetBlock(8, 0.3));
  const remote::SmoothJobOptions job;  // the default run, every phase
  absl::StatusOr<v1::Job> submitted = replicas_[0].client->SubmitJob(mesh, job);
  ASSERT_TRUE(submitted.ok()) << submitted.status();

  absl::StatusOr<std::vector<v1::ProgressEvent>> watched =
      WatchToTheEnd(replicas_[1], submitted->job_id());
  ASSERT_TRUE(watched.ok()) << watched.status();
  const std::vector<v1::ProgressEvent>& events = *watched;
  ASSERT_FALSE(events.empty());
  for (std::size_t i = 0; i < events.size(); ++i) {
    EXPECT_EQ(events[i].job_id(), submitted->job_id());
    EXPECT_EQ(events[i].attempt(), 1u);
    if (i > 0) {
      EXPECT_GT(events[i].sequence(), events[i - 1].sequence()) << "event " << i;
    }
  }
  EXPECT_TRUE(events.back().final());
  // A watcher on another replica, after the end, gets the same events from the first one, with
  // the same numbers.
  absl::StatusOr<std::vector<v1::ProgressEvent>> replayed =
      WatchToTheEnd(replicas_[2], submitted->job_id());
  ASSERT_TRUE(replayed.ok()) << replayed.status();
  ASSERT_EQ(replayed->size(), events.size());
  for (std::size_t i = 0; i < events.size(); ++i) {
    EXPECT_EQ((*replayed)[i].SerializeAsString(), events[i].SerializeAsString()) << "event " << i;
  }
  // Intermediate events are thinned to one per flush; every phase's end is there.
  const auto phase_ends = std::count_if(events.begin(), events.end(),
                                        [](const auto& e) { return e.phase_done() && !e.final(); });

  absl::StatusOr<v1::Job> described = replicas_[2].client->GetJob(submitted->job_id());
  ASSERT_TRUE(described.ok()) << described.status();
  EXPECT_EQ(described->state(), v1::JOB_STATE_SUCCEEDED);
  EXPECT_TRUE(described->result_available());
  absl::StatusOr<remote::RemoteSmoothResult> result =
      replicas_[2].client->GetResult(submitted->job_id());
  ASSERT_TRUE(result.ok()) << result.status();
  EXPECT_EQ(result->result.job_id(), submitted->job_id());
  EXPECT_EQ(phase_ends, result->result.phases_size());
  ExpectSameCoordinates(SingleProcessResult(mesh, job), result->mesh);

  // Handed out once, whichever replica is asked next.
  absl::StatusOr<remote::RemoteSmoothResult> again =
      replicas_[0].client->GetResult(submitted->job_id());
  EXPECT_EQ(again.status().code(), absl::StatusCode::kNotFound) << again.status();
  // Every replica lists it.
  for (Replica& replica : replicas_) {
    absl::StatusOr<std::vector<v1::Job>> listed = replica.client->ListJobs();
    ASSERT_TRUE(listed.ok()) << listed.status();
    ASSERT_EQ(listed->size(), 1u);
    EXPECT_EQ(listed->front().job_id(), submitted->job_id());
  }
  ExpectStoreIdle();
}

TEST_F(ReplicasTest, CancelFromBStopsAJobRunningOnAnotherReplicaAndAQueuedOneAtOnce) {
  StartReplicas(3, {"--workers=1"});
  const v1::Mesh mesh = ToWire(TetBlock(6, 0.3));
  remote::SmoothJobOptions forever;
  forever.parameters = LongRunningParameters();
  // Three replicas with one worker each: three jobs run, the fourth waits in the queue.
  std::vector<std::string> ids;
  for (int i = 0; i < 4; ++i) {
    absl::StatusOr<v1::Job> submitted = replicas_[0].client->SubmitJob(mesh, forever);
    ASSERT_TRUE(submitted.ok()) << submitted.status();
    ids.push_back(submitted->job_id());
    if (i < 3) {
      ASSERT_GE(RunnerOf(ids.back(), 1), 0) << "job " << i << " never ran";
    }
  }
  absl::StatusOr<v1::Job> queued = replicas_[1].client->GetJob(ids[3]);
  ASSERT_TRUE(queued.ok()) << queued.status();
  EXPECT_EQ(queued->state(), v1::JOB_STATE_QUEUED);

  absl::StatusOr<v1::Job> cancelled = replicas_[1].client->CancelJob(ids[3]);
  ASSERT_TRUE(cancelled.ok()) << cancelled.status();
  EXPECT_EQ(cancelled->state(), v1::JOB_STATE_CANCELLED);
  EXPECT_NE(cancelled->error_message().find("cancelled: CancelJob from"), std::string::npos)
      << cancelled->error_message();

  for (int i = 0; i < 3; ++i) {
    const int runner = RunnerOf(ids[i], 1);
    // Cancelled from a replica that does not run it.
    Replica& other = replicas_[(runner + 1) % 3];
    ASSERT_TRUE(other.client->CancelJob(ids[i]).ok());
    ASSERT_TRUE(other.client->WatchJob(ids[i], {}).ok());
    absl::StatusOr<v1::Job> ended = replicas_[(runner + 2) % 3].client->GetJob(ids[i]);
    ASSERT_TRUE(ended.ok()) << ended.status();
    EXPECT_EQ(ended->state(), v1::JOB_STATE_CANCELLED) << ended->DebugString();
    EXPECT_EQ(ended->error_code(), static_cast<int>(absl::StatusCode::kCancelled));
    EXPECT_NE(ended->error_message().find("cancelled: CancelJob from"), std::string::npos)
        << ended->error_message();
    absl::StatusOr<remote::RemoteSmoothResult> result = other.client->GetResult(ids[i]);
    EXPECT_EQ(result.status().code(), absl::StatusCode::kCancelled) << result.status();
  }
  ExpectStoreIdle();
}

TEST_F(ReplicasTest, AKilledReplicasJobIsRestartedElsewhereWithTheSameBitsAndTheWatcherSeesIt) {
  StartReplicas(3, {"--workers=1"});
  const v1::Mesh mesh = ToWire(TetBlock(16, 0.3));
  const remote::SmoothJobOptions job;
  absl::StatusOr<v1::Job> submitted = replicas_[0].client->SubmitJob(mesh, job);
  ASSERT_TRUE(submitted.ok()) << submitted.status();
  const int runner = RunnerOf(submitted->job_id(), 1);
  ASSERT_GE(runner, 0);
  Replica& watcher = replicas_[(runner + 1) % 3];
  Replica& fetcher = replicas_[(runner + 2) % 3];

  std::vector<v1::ProgressEvent> events;
  std::atomic<bool> killed{false};
  absl::Status watched =
      watcher.client->WatchJob(submitted->job_id(), [&](const v1::ProgressEvent& event) {
        events.push_back(event);
        // Killed while it runs: after its first event.
        if (!killed.exchange(true)) {
          ASSERT_EQ(kill(replicas_[runner].process.pid, SIGKILL), 0);
        }
      });
  ASSERT_TRUE(watched.ok()) << watched;
  EXPECT_EQ(WaitForExit(replicas_[runner].process.pid, absl::Seconds(10)), 128 + SIGKILL);

  // The watcher saw the restart as an event, then the second attempt to its end.
  const auto restart = std::find_if(events.begin(), events.end(),
                                    [](const v1::ProgressEvent& e) { return e.restarted(); });
  ASSERT_NE(restart, events.end());
  EXPECT_EQ(restart->attempt(), 2u);
  EXPECT_EQ(events.back().attempt(), 2u);
  EXPECT_TRUE(events.back().final());
  for (std::size_t i = 1; i < events.size(); ++i) {
    EXPECT_GT(events[i].sequence(), events[i - 1].sequence()) << "event " << i;
  }
  EXPECT_GE(RunnerOf(submitted->job_id(), 2), 0);
  EXPECT_NE(RunnerOf(submitted->job_id(), 2), runner);

  // The CLI announces the restart to a user watching (here replaying the stored events), on
  // stderr and in --json, and still ends successfully.
  const cli::testing::RunResult watch =
      cli::testing::RunGetme({"jobs", "watch", submitted->job_id(), "--server", fetcher.address});
  EXPECT_EQ(watch.exit_status, 0) << watch.err;
  EXPECT_NE(watch.err.find(absl::StrCat("[info] job ", submitted->job_id(),
                                        " restarted from the beginning (attempt 2): the replica "
                                        "running it was lost\n")),
            std::string::npos)
      << watch.err;
  const cli::testing::RunResult json = cli::testing::RunGetme(
      {"jobs", "watch", submitted->job_id(), "--server", fetcher.address, "--json"});
  EXPECT_EQ(json.exit_status, 0) << json.err;
  EXPECT_NE(json.out.find(absl::StrCat(R"({"event":"restarted","job_id":")", submitted->job_id(),
                                       R"(","attempt":2})")),
            std::string::npos)
      << json.out;

  absl::StatusOr<remote::RemoteSmoothResult> result =
      fetcher.client->GetResult(submitted->job_id());
  ASSERT_TRUE(result.ok()) << result.status();
  ExpectSameCoordinates(SingleProcessResult(mesh, job), result->mesh);
  ExpectStoreIdle();
}

TEST_F(ReplicasTest, SixteenClientsAgainstAClusterQueueLimitLoseAndDuplicateNothing) {
  StartReplicas(3, {"--workers=1", "--max_queued_jobs=2"});
  const v1::Mesh mesh = ToWire(TetBlock(8, 0.3));
  constexpr int kClients = 16;
  std::vector<std::string> accepted(kClients);
  std::vector<absl::StatusCode> codes(kClients, absl::StatusCode::kUnknown);
  std::vector<std::thread> clients;
  for (int i = 0; i < kClients; ++i) {
    clients.emplace_back([&, i] {
      remote::CallOptions once;
      once.retry.max_attempts = 1;
      absl::StatusOr<v1::Job> submitted = replicas_[i % 3].client->SubmitJob(mesh, {}, once);
      codes[i] = submitted.status().code();
      if (submitted.ok()) accepted[i] = submitted->job_id();
    });
  }
  for (std::thread& client : clients) client.join();

  std::set<std::string> ids;
  int refused = 0;
  for (int i = 0; i < kClients; ++i) {
    if (codes[i] == absl::StatusCode::kOk) {
      EXPECT_TRUE(ids.insert(accepted[i]).second) << "duplicate id " << accepted[i];
    } else {
      EXPECT_EQ(codes[i], absl::StatusCode::kResourceExhausted) << "client " << i;
      ++refused;
    }
  }
  EXPECT_GT(refused, 0) << "the limit of 2 queued jobs never bit";
  // The two queue slots always take the first two; more get in only if a replica takes a job
  // before the others have been refused, which all 16 arriving at once may not leave time for.
  EXPECT_GE(ids.size(), 2u);
  // Every accepted job ends SUCCEEDED with its result, fetched from another replica.
  for (const std::string& id : ids) {
    ASSERT_TRUE(replicas_[1].client->WatchJob(id, {}).ok());
    absl::StatusOr<remote::RemoteSmoothResult> result = replicas_[2].client->GetResult(id);
    ASSERT_TRUE(result.ok()) << id << ": " << result.status();
    EXPECT_EQ(result->mesh.coordinates_size(), mesh.coordinates_size());
  }
  absl::StatusOr<std::vector<v1::Job>> listed = replicas_[0].client->ListJobs();
  ASSERT_TRUE(listed.ok()) << listed.status();
  std::set<std::string> listed_ids;
  for (const v1::Job& job : *listed) {
    EXPECT_EQ(job.state(), v1::JOB_STATE_SUCCEEDED) << job.job_id();
    listed_ids.insert(job.job_id());
  }
  EXPECT_EQ(listed_ids, ids);
  ExpectStoreIdle();
}

TEST_F(ReplicasTest, TheHttpGatewayAndDashboardOfAnyReplicaSeeTheWholeCluster) {
  StartReplicas(3, {"--http_listen=127.0.0.1:0"});
  std::vector<std::unique_ptr<httplib::Client>> http;
  for (const Replica& replica : replicas_) {
    ASSERT_GT(replica.http_port, 0);
    http.push_back(std::make_unique<httplib::Client>("127.0.0.1", replica.http_port));
  }
  // Queued over HTTP (the JSON body's mesh is what the store keeps) on A.
  const HttpReply created =
      HttpPost(*http[0], "/v1/jobs", CreateJobJson(ToWire(TetBlock(4, 0.3)), {}));
  ASSERT_EQ(created.status, 200) << created.body;
  const std::string id = ParseJson<v1::Job>(created.body).job_id();

  // Followed live on C: progress events, then the result summary, then the job's end.
  const std::vector<SseEvent> events = ReadEventStream(*http[2], id);
  ASSERT_GE(events.size(), 3u);
  EXPECT_EQ(events.front().name, "progress");
  EXPECT_EQ(events[events.size() - 2].name, "result");
  EXPECT_EQ(events.back().name, "end");
  EXPECT_EQ(ParseJson<v1::Job>(events.back().data).state(), v1::JOB_STATE_SUCCEEDED);

  // Listed and reported on B.
  const HttpReply listed = HttpGet(*http[1], "/v1/jobs");
  ASSERT_EQ(listed.status, 200) << listed.body;
  const auto jobs = ParseJson<v1::ListJobsResponse>(listed.body);
  ASSERT_EQ(jobs.jobs_size(), 1);
  EXPECT_EQ(jobs.jobs(0).job_id(), id);
  const HttpReply report = HttpGet(*http[1], absl::StrCat("/v1/jobs/", id, "/report"));
  ASSERT_EQ(report.status, 200) << report.body;
  EXPECT_EQ(ParseJson<v1::SmoothResult>(report.body).job_id(), id);

  // Every replica's /metrics counts the cluster: three live replicas, an empty shared queue.
  for (auto& client : http) {
    const std::map<std::string, double> metrics = ScrapeMetrics(*client);
    EXPECT_EQ(metrics.at("getme_live_replicas"), 3);
    EXPECT_EQ(metrics.at("getme_queue_length"), 0);
  }
  ExpectStoreIdle();
}

TEST_F(ReplicasTest, AJobIsVisibleOnlyToItsOwnerOnEveryReplica) {
  StartReplicas(2, {absl::StrCat("--auth_tokens_file=", TokensFile())});
  remote::SmootherClient alice_on_a(ChannelWithToken(replicas_[0].port, kAliceToken));
  remote::SmootherClient alice_on_b(ChannelWithToken(replicas_[1].port, kAliceToken));
  remote::SmootherClient bob_on_b(ChannelWithToken(replicas_[1].port, kBobToken));
  absl::StatusOr<v1::Job> submitted = alice_on_a.SubmitJob(ToWire(TetBlock(4, 0.3)), {});
  ASSERT_TRUE(submitted.ok()) << submitted.status();
  ASSERT_TRUE(alice_on_b.WatchJob(submitted->job_id(), {}).ok());

  // Bob is told exactly what an unknown id gets.
  absl::StatusOr<v1::Job> bobs_view = bob_on_b.GetJob(submitted->job_id());
  absl::StatusOr<v1::Job> unknown = bob_on_b.GetJob("000000000000");
  EXPECT_EQ(bobs_view.status().code(), absl::StatusCode::kNotFound);
  EXPECT_EQ(unknown.status().code(), absl::StatusCode::kNotFound);
  EXPECT_EQ(std::string(bobs_view.status().message()),
            absl::StrCat("no job with id '", submitted->job_id(),
                         "' (unknown, or forgotten after its result expired)"));
  EXPECT_EQ(bob_on_b.GetResult(submitted->job_id()).status().code(), absl::StatusCode::kNotFound);
  EXPECT_EQ(bob_on_b.CancelJob(submitted->job_id()).status().code(), absl::StatusCode::kNotFound);
  absl::StatusOr<std::vector<v1::Job>> bobs_jobs = bob_on_b.ListJobs();
  ASSERT_TRUE(bobs_jobs.ok()) << bobs_jobs.status();
  EXPECT_TRUE(bobs_jobs->empty());

  absl::StatusOr<remote::RemoteSmoothResult> result = alice_on_b.GetResult(submitted->job_id());
  ASSERT_TRUE(result.ok()) << result.status();
  // No token at all: refused by every replica.
  remote::SmootherClient anonymous(remote::SmootherClient::CreateChannel(replicas_[1].address));
  EXPECT_EQ(anonymous.ListJobs().status().code(), absl::StatusCode::kUnauthenticated);
}

// A job taken just before SIGTERM is not in the replica's job registry until its mesh is rebuilt
// from the stored upload. The drain once waited only for the registry: such a job then started
// after the drain had decided nothing was running, ran on without its grace period, and the
// process never exited.
TEST_F(ReplicasTest, SigtermWhileATakenJobsMeshIsRebuiltHandsItBackWithinTheGrace) {
  StartReplicas(1, {"--workers=1", "--shutdown_grace=200ms"});
  // A large upload, so that rebuilding its mesh leaves time for the signal to land between the
  // take and the start.
  const v1::Mesh mesh = ToWire(TetBlock(40, 0.3));
  remote::SmoothJobOptions forever;
  forever.parameters = LongRunningParameters();
  absl::StatusOr<v1::Job> submitted = replicas_[0].client->SubmitJob(mesh, forever);
  ASSERT_TRUE(submitted.ok()) << submitted.status();
  const std::string& log_path = replicas_[0].process.log_path;
  const std::string taken = absl::StrCat("job=", submitted->job_id(), " phase=taken attempt=1 ");
  const absl::Time deadline = absl::Now() + absl::Seconds(60);
  while (ReadFile(log_path).find(taken) == std::string::npos && absl::Now() < deadline) {
    absl::SleepFor(absl::Microseconds(500));
  }
  ASSERT_NE(ReadFile(log_path).find(taken), std::string::npos) << ReadFile(log_path);
  ASSERT_EQ(kill(replicas_[0].process.pid, SIGTERM), 0);
  const bool started_first = absl::StrContains(
      ReadFile(log_path), absl::StrCat("job=", submitted->job_id(), " phase=start "));
  EXPECT_EQ(WaitForExit(replicas_[0].process.pid, absl::Seconds(60)), 0) << ReadFile(log_path);
  if (started_first) std::printf("the job had started before the signal: the race was not hit\n");

  // Handed back: the next replica runs it again.
  StartReplicas(1, {"--workers=1"});
  EXPECT_EQ(RunnerOf(submitted->job_id(), 2), 1);
  ASSERT_TRUE(replicas_[1].client->CancelJob(submitted->job_id()).ok());
  ASSERT_TRUE(replicas_[1].client->WatchJob(submitted->job_id(), {}).ok());
  ExpectStoreIdle();
}

TEST_F(ReplicasTest, SigtermLeavesQueuedJobsInTheStoreAndHandsRunningOnesToTheOthers) {
  StartReplicas(1, {"--workers=1", "--shutdown_grace=500ms"});
  const v1::Mesh mesh = ToWire(TetBlock(6, 0.3));
  remote::SmoothJobOptions forever;
  forever.parameters = LongRunningParameters();
  absl::StatusOr<v1::Job> running = replicas_[0].client->SubmitJob(mesh, forever);
  ASSERT_TRUE(running.ok()) << running.status();
  ASSERT_EQ(RunnerOf(running->job_id(), 1), 0);
  absl::StatusOr<v1::Job> queued = replicas_[0].client->SubmitJob(mesh, forever);
  ASSERT_TRUE(queued.ok()) << queued.status();

  ASSERT_EQ(kill(replicas_[0].process.pid, SIGTERM), 0);
  EXPECT_EQ(WaitForExit(replicas_[0].process.pid, absl::Seconds(30)), 0)
      << ReadFile(replicas_[0].process.log_path);

  // A replica started afterwards finds both: the queued one as it was, the running one again
  // from the beginning.
  StartReplicas(1, {"--workers=2"});
  remote::SmootherClient& other = *replicas_[1].client;
  EXPECT_EQ(RunnerOf(queued->job_id(), 1), 1);
  EXPECT_EQ(RunnerOf(running->job_id(), 2), 1);
  for (const v1::Job* job : {&*running, &*queued}) {
    absl::StatusOr<v1::Job> described = other.GetJob(job->job_id());
    ASSERT_TRUE(described.ok()) << described.status();
    EXPECT_EQ(described->state(), v1::JOB_STATE_RUNNING) << described->DebugString();
    ASSERT_TRUE(other.CancelJob(job->job_id()).ok());
    ASSERT_TRUE(other.WatchJob(job->job_id(), {}).ok());
  }
  ExpectStoreIdle();
}

TEST_F(ReplicasTest, AResultTheFullStoreCannotKeepFailsTheJobWithResourceExhausted) {
  StartReplicas(1, {"--workers=1"});
  // The one worker is kept busy until the job under test is queued (its upload in the store).
  remote::SmoothJobOptions forever;
  forever.parameters = LongRunningParameters();
  absl::StatusOr<v1::Job> blocker =
      replicas_[0].client->SubmitJob(ToWire(TetBlock(4, 0.3)), forever);
  ASSERT_TRUE(blocker.ok()) << blocker.status();
  ASSERT_EQ(RunnerOf(blocker->job_id(), 1), 0);
  const v1::Mesh mesh = ToWire(TetBlock(16, 0.3));  // a result of about 0.5 MB
  absl::StatusOr<v1::Job> submitted = replicas_[0].client->SubmitJob(mesh, {});
  ASSERT_TRUE(submitted.ok()) << submitted.status();
  // Then Redis is allowed 100 kB more than it holds: the result cannot fit.
  absl::StatusOr<redis::RedisReply> info = store_->Command({"INFO", "memory"});
  ASSERT_TRUE(info.ok()) << info.status();
  const std::size_t at = info->str().find("used_memory:");
  ASSERT_NE(at, std::string::npos);
  std::int64_t used = 0;
  ASSERT_TRUE(
      absl::SimpleAtoi(info->str().substr(at + 12, info->str().find('\r', at) - at - 12), &used));
  ASSERT_TRUE(store_->Command({"CONFIG", "SET", "maxmemory-policy", "noeviction"}).ok());
  ASSERT_TRUE(store_->Command({"CONFIG", "SET", "maxmemory", absl::StrCat(used + 100'000)}).ok());
  ASSERT_TRUE(replicas_[0].client->CancelJob(blocker->job_id()).ok());

  ASSERT_TRUE(replicas_[0].client->WatchJob(submitted->job_id(), {}).ok());
  absl::StatusOr<v1::Job> ended = replicas_[0].client->GetJob(submitted->job_id());
  ASSERT_TRUE(ended.ok()) << ended.status();
  EXPECT_EQ(ended->state(), v1::JOB_STATE_FAILED);
  EXPECT_EQ(ended->error_code(), static_cast<int>(absl::StatusCode::kResourceExhausted));
  EXPECT_NE(ended->error_message().find("the shared job store could not keep its result"),
            std::string::npos)
      << ended->error_message();
  EXPECT_EQ(replicas_[0].client->GetResult(submitted->job_id()).status().code(),
            absl::StatusCode::kResourceExhausted);
  ASSERT_TRUE(store_->Command({"CONFIG", "SET", "maxmemory", "0"}).ok());
  ExpectStoreIdle();
}

TEST_F(ReplicasTest, TheJobListIsNewestFirstSaysWhichResultsWaitAndForgetsExpiredJobs) {
  StartReplicas(2);
  const v1::Mesh mesh = ToWire(TetBlock(4, 0.3));
  std::vector<std::string> ids;  // oldest first
  for (int i = 0; i < 4; ++i) {
    absl::StatusOr<v1::Job> submitted = replicas_[i % 2].client->SubmitJob(mesh, {});
    ASSERT_TRUE(submitted.ok()) << submitted.status();
    ASSERT_TRUE(replicas_[0].client->WatchJob(submitted->job_id(), {}).ok());
    ids.push_back(submitted->job_id());
    absl::SleepFor(absl::Milliseconds(2));  // distinct creation times
  }
  ASSERT_TRUE(replicas_[1].client->GetResult(ids[1]).ok());  // fetched: no longer available
  // What the time to live does to a job: its record is gone, its index entries stay.
  ASSERT_EQ(StoreInteger({"DEL", "getme:job:" + ids[2]}), 1);

  for (Replica& replica : replicas_) {
    absl::StatusOr<std::vector<v1::Job>> listed = replica.client->ListJobs();
    ASSERT_TRUE(listed.ok()) << listed.status();
    ASSERT_EQ(listed->size(), 3u);
    EXPECT_EQ((*listed)[0].job_id(), ids[3]);
    EXPECT_EQ((*listed)[1].job_id(), ids[1]);
    EXPECT_EQ((*listed)[2].job_id(), ids[0]);
    for (const v1::Job& job : *listed) {
      EXPECT_EQ(job.state(), v1::JOB_STATE_SUCCEEDED) << job.job_id();
      EXPECT_EQ(job.result_available(), job.job_id() != ids[1]) << job.job_id();
      EXPECT_EQ(job.elements(), 384u) << job.job_id();  // 6 × 4³ tetrahedra
    }
  }
  EXPECT_EQ(StoreInteger({"ZCARD", "getme:jobs"}), 3);
  for (const std::string& id : {ids[0], ids[3]})
    ASSERT_TRUE(replicas_[0].client->GetResult(id).ok());
  ExpectStoreIdle();
}

// A 1 ms time to live: every result a Smooth call did not fetch is gone before anyone could
// fetch it. The Smooth calls still get theirs (the store keeps a result a Smooth call waits for at
// least one lease); a SubmitJob result is gone as the time to live says.
TEST_F(ReplicasTest, ASmoothCallGetsItsResultHoweverShortTheTimeToLive) {
  StartReplicas(1, {"--result_ttl=1ms"});
  const v1::Mesh mesh = ToWire(TetBlock(4, 0.3));
  for (int call = 0; call < 3; ++call) {
    absl::StatusOr<remote::RemoteSmoothResult> result = replicas_[0].client->Smooth(mesh, {}, {});
    ASSERT_TRUE(result.ok()) << result.status();
    EXPECT_EQ(result->mesh.coordinates().size(), mesh.coordinates().size());
  }
  absl::StatusOr<v1::Job> submitted = replicas_[0].client->SubmitJob(mesh, {});
  ASSERT_TRUE(submitted.ok()) << submitted.status();
  ASSERT_TRUE(replicas_[0].client->WatchJob(submitted->job_id(), {}).ok());
  absl::SleepFor(absl::Milliseconds(50));
  EXPECT_EQ(replicas_[0].client->GetResult(submitted->job_id()).status().code(),
            absl::StatusCode::kNotFound);
  ExpectStoreIdle();
}

TEST_F(ReplicasTest, AReplicaThatCannotReachItsStoreRefusesToStart) {
  const std::string log = getme::testing::DeleteWhenTheRunPasses(
      absl::StrCat(::testing::TempDir(), "/getme-replica-nostore-", getpid()));
  // A port nothing listens on: the one the test's redis has, once it is gone.
  const std::string url = redis_->url();
  redis_.reset();
  ServerProcess server = SpawnServer(log, {absl::StrCat("--job_store=", url)});
  EXPECT_EQ(WaitForExit(server.pid, absl::Seconds(20)), 1);
  EXPECT_NE(ReadFile(log).find("--job_store: redis: cannot connect to " + url), std::string::npos)
      << ReadFile(log);
}

// The store over TLS with a password and a client certificate, as a managed Redis would be
// reached: the replicas share jobs through it as through a plain one.
class ReplicasOverTlsTest : public ReplicasTest {
 protected:
  RedisServerProcess::Options RedisOptions() const override {
    RedisServerProcess::Options options =
        redis::testing::TlsServerOptions(/*require_client_certificate=*/true);
    options.password = "s3cret";
    return options;
  }
  std::string StoreUrl() const override {
    const TestCertificates& certificates = GetTestCertificates();
    return absl::StrCat(redis_->url(), "&cert=", certificates.client_cert,
                        "&key=", certificates.client_key);
  }
};

TEST_F(ReplicasOverTlsTest, SubmitOnAFetchOnBGivesTheSingleProcessBits) {
  StartReplicas(2);
  const v1::Mesh mesh = ToWire(TetBlock(6, 0.3));
  const remote::SmoothJobOptions job;
  absl::StatusOr<v1::Job> submitted = replicas_[0].client->SubmitJob(mesh, job);
  ASSERT_TRUE(submitted.ok()) << submitted.status();
  absl::StatusOr<std::vector<v1::ProgressEvent>> events =
      WatchToTheEnd(replicas_[1], submitted->job_id());
  ASSERT_TRUE(events.ok()) << events.status();
  ASSERT_FALSE(events->empty());
  EXPECT_TRUE(events->back().final());
  absl::StatusOr<remote::RemoteSmoothResult> result =
      replicas_[1].client->GetResult(submitted->job_id());
  ASSERT_TRUE(result.ok()) << result.status();
  ExpectSameCoordinates(SingleProcessResult(mesh, job), result->mesh);
  ExpectStoreIdle();
}

TEST_F(ReplicasOverTlsTest, AReplicaThatDoesNotTrustTheStoresCertificateRefusesToStart) {
  const std::string log = getme::testing::DeleteWhenTheRunPasses(
      absl::StrCat(::testing::TempDir(), "/getme-replica-untrusted-", getpid()));
  const TestCertificates& certificates = GetTestCertificates();
  const std::string url = absl::StrCat(
      "rediss://:s3cret@127.0.0.1:", redis_->port(), "/0?cacert=", certificates.other_ca_cert,
      "&cert=", certificates.client_cert, "&key=", certificates.client_key);
  ServerProcess server = SpawnServer(log, {absl::StrCat("--job_store=", url)});
  EXPECT_EQ(WaitForExit(server.pid, absl::Seconds(20)), 1);
  // The log names the store without its password, and why the handshake failed.
  const std::string text = ReadFile(log);
  EXPECT_NE(text.find(absl::StrCat(
                "--job_store: redis: TLS handshake with rediss://:***@127.0.0.1:", redis_->port(),
                "/0 failed: certificate verify failed")),
            std::string::npos)
      << text;
  EXPECT_EQ(text.find("s3cret"), std::string::npos) << text;
}

}  // namespace
}  // namespace getme::server::testing
