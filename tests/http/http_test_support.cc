#include "http_test_support.h"

#include <regex>

#include "absl/strings/numbers.h"
#include "absl/strings/str_cat.h"
#include "absl/strings/str_split.h"
#include "absl/strings/strip.h"
#include "google/protobuf/util/json_util.h"

namespace getme::server::testing {

HttpTestServer StartHttpTestServer(ServerOptions options) {
  options.http_listen = "127.0.0.1:0";
  HttpTestServer test;
  test.grpc = StartTestServer(options);
  const int port = test.grpc.server->http_port();
  EXPECT_GT(port, 0);
  test.http = std::make_unique<httplib::Client>("127.0.0.1", port);
  test.http->set_read_timeout(30, 0);
  return test;
}

HttpReply HttpGet(httplib::Client& client, const std::string& path) {
  HttpReply reply;
  if (auto result = client.Get(path)) {
    reply = {result->status, result->body, result->get_header_value("Content-Type")};
  }
  return reply;
}

HttpReply HttpPost(httplib::Client& client, const std::string& path, const std::string& body) {
  HttpReply reply;
  if (auto result = client.Post(path, body, "application/json")) {
    reply = {result->status, result->body, result->get_header_value("Content-Type")};
  }
  return reply;
}

namespace {

std::map<std::string, double> ParseMetrics(const std::string& text) {
  const std::regex sample(
      R"re(([a-zA-Z_:][a-zA-Z0-9_:]*)(\{([a-zA-Z_][a-zA-Z0-9_]*="([^"\\]|\\.)*",?)*\})? (\S+))re");
  const std::regex type(R"(# TYPE ([a-zA-Z_:][a-zA-Z0-9_:]*) (counter|gauge|histogram))");
  std::map<std::string, double> samples;
  std::string typed;
  for (absl::string_view view : absl::StrSplit(text, '\n', absl::SkipEmpty())) {
    const std::string line(view);
    std::smatch match;
    if (std::regex_match(line, match, type)) {
      typed = match[1];
    } else if (line.starts_with("# HELP ")) {
      continue;
    } else if (std::regex_match(line, match, sample)) {
      EXPECT_TRUE(match[1].str().starts_with(typed)) << line << " has no # TYPE";
      double value = 0;
      EXPECT_TRUE(absl::SimpleAtod(match[5].str(), &value)) << line;
      samples[match[1].str() + match[2].str()] = value;
    } else {
      ADD_FAILURE() << "not Prometheus text: " << line;
    }
  }
  return samples;
}

}  // namespace

std::map<std::string, double> ScrapeMetrics(httplib::Client& client) {
  const HttpReply reply = HttpGet(client, "/metrics");
  EXPECT_EQ(reply.status, 200);
  EXPECT_EQ(reply.content_type, "text/plain; version=0.0.4");
  return ParseMetrics(reply.body);
}

std::string CreateJobJson(const v1::Mesh& mesh, const v1::SmoothingParameters& parameters) {
  v1::CreateJobRequest request;
  *request.mutable_mesh() = mesh;
  *request.mutable_parameters() = parameters;
  std::string json;
  EXPECT_TRUE(google::protobuf::util::MessageToJsonString(request, &json).ok());
  return json;
}

std::vector<SseEvent> ReadEventStream(httplib::Client& client, const std::string& job_id,
                                      std::atomic<bool>* opened) {
  std::string text;
  auto result = client.Get(absl::StrCat("/v1/jobs/", job_id, "/events"),
                           [&text, opened](const char* data, std::size_t length) {
                             text.append(data, length);
                             if (opened != nullptr) opened->store(true);
                             return true;
                           });
  EXPECT_TRUE(result) << "event stream failed: " << httplib::to_string(result.error());
  if (result) {
    EXPECT_EQ(result->status, 200);
    EXPECT_EQ(result->get_header_value("Content-Type"), "text/event-stream");
  }
  std::vector<SseEvent> events;
  for (absl::string_view frame : absl::StrSplit(text, "\n\n", absl::SkipEmpty())) {
    SseEvent event;
    for (absl::string_view line : absl::StrSplit(frame, '\n')) {
      if (absl::ConsumePrefix(&line, "event: ")) event.name = std::string(line);
      if (absl::ConsumePrefix(&line, "data: ")) event.data = std::string(line);
    }
    if (!event.name.empty()) events.push_back(std::move(event));
  }
  return events;
}

}  // namespace getme::server::testing
