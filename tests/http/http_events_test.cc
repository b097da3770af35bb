// GET /v1/jobs/{id}/events: the WatchJob progress stream as Server-Sent Events, ending with the
// result summary and the job's final state; watchers that stop reading hold nothing up.
#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <atomic>
#include <string>
#include <thread>

#include "absl/strings/str_cat.h"
#include "absl/time/clock.h"
#include "getme_server/job.h"
#include "gmock/gmock.h"
#include "gtest/gtest.h"
#include "http_test_support.h"

namespace getme::server::testing {
namespace {

v1::SmoothingParameters SimultaneousOnly() {
  v1::SmoothingParameters parameters;
  parameters.set_method(v1::METHOD_SIMULTANEOUS);
  parameters.set_simultaneous_tolerance(0);  // every one of the max iterations runs
  parameters.set_simultaneous_max_iterations(60);
  return parameters;
}

// The events of GET /v1/jobs/{id}/trace ({"events": [...]}), each as its JSON text.
std::vector<SseEvent> TraceEvents(const std::string& body) {
  std::vector<SseEvent> events;
  std::size_t at = body.find('[');
  int depth = 0;
  std::size_t start = 0;
  for (std::size_t i = at + 1; at != std::string::npos && i < body.size(); ++i) {
    if (body[i] == '{' && depth++ == 0) start = i;
    if (body[i] == '}' && --depth == 0)
      events.push_back({"trace", body.substr(start, i - start + 1)});
  }
  return events;
}

std::string PostJob(HttpTestServer& test, const v1::Mesh& mesh,
                    const v1::SmoothingParameters& parameters) {
  const HttpReply posted = HttpPost(*test.http, "/v1/jobs", CreateJobJson(mesh, parameters));
  EXPECT_EQ(posted.status, 200) << posted.body;
  return ParseJson<v1::Job>(posted.body).job_id();
}

TEST(HttpEventsTest, StreamCarriesEveryProgressEventInOrderThenResultThenEnd) {
  ServerOptions options = TestOptions();
  options.workers = 1;
  HttpTestServer test = StartHttpTestServer(options);
  // A blocker keeps the job queued until the stream is open, so the stream sees all its events.
  const std::string blocker = PostJob(test, ToWire(TetBlock(4, 0.3)), LongRunningParameters());
  const std::string id = PostJob(test, ToWire(TetBlock(6, 0.3)), SimultaneousOnly());
  std::vector<SseEvent> events;
  std::atomic<bool> opened{false};
  std::thread reader([&] { events = ReadEventStream(*test.http, id, &opened); });
  const absl::Time deadline = absl::Now() + absl::Seconds(30);
  while (!opened.load() && absl::Now() < deadline) absl::SleepFor(absl::Milliseconds(5));
  httplib::Client other("127.0.0.1", test.grpc.server->http_port());
  ASSERT_EQ(HttpPost(other, "/v1/jobs/" + blocker + ":cancel", "").status, 200);
  reader.join();
  // 60 iterations, the phase_done event, the final event; then result and end.
  ASSERT_EQ(events.size(), 64u);
  EXPECT_EQ(events[events.size() - 1].name, "end");
  EXPECT_EQ(events[events.size() - 2].name, "result");

  std::uint64_t last_sequence = 0;
  int finals = 0;
  v1::ProgressEvent last;
  for (std::size_t i = 0; i + 2 < events.size(); ++i) {
    ASSERT_EQ(events[i].name, "progress") << i;
    const auto event = ParseJson<v1::ProgressEvent>(events[i].data);
    EXPECT_EQ(event.job_id(), id);
    EXPECT_EQ(event.sequence(), last_sequence + 1) << "every event, in order";
    last_sequence = event.sequence();
    finals += event.final() ? 1 : 0;
    last = event;
  }
  EXPECT_EQ(finals, 1);
  EXPECT_TRUE(last.final()) << "the final progress event comes last";

  const auto result = ParseJson<v1::SmoothResult>(events[events.size() - 2].data);
  EXPECT_EQ(result.job_id(), id);
  EXPECT_EQ(result.iterations_simultaneous(), 60);
  EXPECT_EQ(last.q_min(), result.after().q_min());
  std::int64_t histogram_total = 0;
  for (std::int64_t count : result.before().histogram()) histogram_total += count;
  EXPECT_EQ(histogram_total, result.before().elements());
  const auto end = ParseJson<v1::Job>(events.back().data);
  EXPECT_EQ(end.state(), v1::JOB_STATE_SUCCEEDED);

  // The trace has the whole run (fewer than Job::kMaxTrace events here, so none thinned out).
  const HttpReply trace = HttpGet(*test.http, "/v1/jobs/" + id + "/trace");
  ASSERT_EQ(trace.status, 200);
  const std::vector<SseEvent> as_events = TraceEvents(trace.body);
  ASSERT_EQ(as_events.size(), events.size() - 2);
  for (std::size_t i = 0; i < as_events.size(); ++i) {
    EXPECT_EQ(ParseJson<v1::ProgressEvent>(as_events[i].data).sequence(), i + 1);
  }

  // Reconnecting to a finished job replays its final event, result and end (page reloads).
  const std::vector<SseEvent> again = ReadEventStream(*test.http, id);
  ASSERT_EQ(again.size(), 3u);
  EXPECT_EQ(ParseJson<v1::ProgressEvent>(again[0].data).sequence(), last.sequence());
  EXPECT_EQ(again[2].name, "end");
}

TEST(HttpEventsTest, CancelledJobStreamEndsWithCancelledAndNoResult) {
  HttpTestServer test = StartHttpTestServer();
  const std::string id = PostJob(test, ToWire(TetBlock(4, 0.3)), LongRunningParameters());
  WaitForState(*test.grpc.stub, id, v1::JOB_STATE_RUNNING);
  std::thread canceller([&] {
    absl::SleepFor(absl::Milliseconds(300));
    EXPECT_EQ(HttpPost(*test.http, "/v1/jobs/" + id + ":cancel", "").status, 200);
  });
  httplib::Client watcher("127.0.0.1", test.grpc.server->http_port());
  const std::vector<SseEvent> events = ReadEventStream(watcher, id);
  canceller.join();
  ASSERT_GE(events.size(), 2u);
  EXPECT_EQ(events.back().name, "end");
  EXPECT_EQ(ParseJson<v1::Job>(events.back().data).state(), v1::JOB_STATE_CANCELLED);
  EXPECT_TRUE(ParseJson<v1::ProgressEvent>(events[events.size() - 2].data).final());
  for (const SseEvent& event : events) EXPECT_NE(event.name, "result");

  // Thousands of events (one per 200 picks): the trace is thinned, keeps order and the end.
  const auto trace = TraceEvents(HttpGet(*test.http, "/v1/jobs/" + id + "/trace").body);
  const auto last = ParseJson<v1::ProgressEvent>(events[events.size() - 2].data);
  ASSERT_FALSE(trace.empty());
  EXPECT_LE(trace.size(), Job::kMaxTrace);
  EXPECT_EQ(ParseJson<v1::ProgressEvent>(trace.back().data).sequence(), last.sequence());
  std::uint64_t previous = 0;
  for (const SseEvent& event : trace) {
    const std::uint64_t sequence = ParseJson<v1::ProgressEvent>(event.data).sequence();
    EXPECT_GT(sequence, previous);
    previous = sequence;
  }
}

// Opens an event stream on a raw socket and never reads from it.
int OpenStalledStream(int port, const std::string& id) {
  const int fd = socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_port = htons(static_cast<std::uint16_t>(port));
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  EXPECT_EQ(connect(fd, reinterpret_cast<sockaddr*>(&address), sizeof(address)), 0);
  const int small = 1024;  // a tiny receive window fills at once
  setsockopt(fd, SOL_SOCKET, SO_RCVBUF, &small, sizeof(small));
  const std::string request =
      absl::StrCat("GET /v1/jobs/", id, "/events HTTP/1.1\r\nHost: 127.0.0.1\r\n\r\n");
  EXPECT_EQ(send(fd, request.data(), request.size(), 0), static_cast<ssize_t>(request.size()));
  return fd;
}

TEST(HttpEventsTest, StalledAndVanishedWatchersHoldUpNeitherTheJobNorOtherWatchers) {
  ServerOptions options = TestOptions();
  HttpTestServer test = StartHttpTestServer(options);
  v1::SmoothingParameters parameters = SimultaneousOnly();
  parameters.set_simultaneous_max_iterations(400);
  const std::string id = PostJob(test, ToWire(TetBlock(6, 0.3)), parameters);
  const int stalled = OpenStalledStream(test.grpc.server->http_port(), id);
  const int vanished = OpenStalledStream(test.grpc.server->http_port(), id);
  close(vanished);

  httplib::Client reader("127.0.0.1", test.grpc.server->http_port());
  const std::vector<SseEvent> events = ReadEventStream(reader, id);
  ASSERT_FALSE(events.empty());
  EXPECT_EQ(ParseJson<v1::Job>(events.back().data).state(), v1::JOB_STATE_SUCCEEDED);
  close(stalled);
}

TEST(HttpEventsTest, ShutdownEndsOpenStreams) {
  HttpTestServer test = StartHttpTestServer();
  const std::string id = PostJob(test, ToWire(TetBlock(4, 0.3)), LongRunningParameters());
  WaitForState(*test.grpc.stub, id, v1::JOB_STATE_RUNNING);
  std::thread shutdown([&] {
    absl::SleepFor(absl::Milliseconds(300));
    test.grpc.server->Shutdown(absl::ZeroDuration());
  });
  const absl::Time start = absl::Now();
  const std::vector<SseEvent> events = ReadEventStream(*test.http, id);
  shutdown.join();
  EXPECT_LT(absl::Now() - start, absl::Seconds(10));
  ASSERT_FALSE(events.empty());
  EXPECT_EQ(events.back().name, "end");
  EXPECT_EQ(ParseJson<v1::Job>(events.back().data).state(), v1::JOB_STATE_CANCELLED);
}

}  // namespace
}  // namespace getme::server::testing
