#pragma once

#include <atomic>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "absl/status/statusor.h"
#include "getme/v1/smoother.pb.h"
#include "google/protobuf/util/json_util.h"
#include "gtest/gtest.h"
#include "httplib.h"
#include "server_test_support.h"

namespace getme::server::testing {

// An in-process server with its HTTP gateway on a free loopback port, and clients for both.
struct HttpTestServer {
  TestServer grpc;
  std::unique_ptr<httplib::Client> http;
};
HttpTestServer StartHttpTestServer(ServerOptions options = TestOptions());

// A response's status and body; status -1 when the request failed at the transport.
struct HttpReply {
  int status = -1;
  std::string body;
  std::string content_type;
};
HttpReply HttpGet(httplib::Client& client, const std::string& path);
HttpReply HttpPost(httplib::Client& client, const std::string& path, const std::string& body);

// Parses a JSON response with protobuf's own parser (fails the test on bad JSON).
template <typename Message>
Message ParseJson(const std::string& json) {
  Message message;
  const auto status = google::protobuf::util::JsonStringToMessage(json, &message);
  EXPECT_TRUE(status.ok()) << status.ToString() << " in " << json;
  return message;
}

// GET /metrics parsed: every sample "name{labels} value" by "name{labels}". Fails the test on a
// status other than 200, a line that is neither a sample nor a # HELP / # TYPE comment, or a
// sample without a # TYPE before it.
std::map<std::string, double> ScrapeMetrics(httplib::Client& client);

// The JSON body of POST /v1/jobs for a mesh.
std::string CreateJobJson(const v1::Mesh& mesh, const v1::SmoothingParameters& parameters);

// One Server-Sent Event (its "event:" name and "data:" payload).
struct SseEvent {
  std::string name;
  std::string data;
};
// Reads GET /v1/jobs/{id}/events until the server closes the stream.
// The whole event stream of a job, read to its end. `opened`, if given, is set when the first
// bytes arrive: the server has attached the watcher by then.
std::vector<SseEvent> ReadEventStream(httplib::Client& client, const std::string& job_id,
                                      std::atomic<bool>* opened = nullptr);

}  // namespace getme::server::testing
