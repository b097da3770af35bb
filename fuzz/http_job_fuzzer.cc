// libFuzzer target: the body of the HTTP gateway's POST /v1/jobs, through the same function the
// endpoint calls (CreateJobFromJson: protobuf JSON, then the checks every front end shares). The
// job is created but not queued, so no engine runs.
#include <cstddef>
#include <cstdint>
#include <string>

#include "absl/strings/str_cat.h"
#include "fuzz_check.h"
#include "getme/v1/smoother.pb.h"
#include "getme_server/http_json.h"
#include "getme_server/job_registry.h"
#include "getme_server/job_submission.h"
#include "getme_server/server_options.h"
#include "getme_wire/mesh_fields.h"
#include "google/protobuf/struct.pb.h"
#include "google/protobuf/util/json_util.h"
#include "google/protobuf/util/message_differencer.h"

namespace getme::fuzz {
namespace {

// The gateway's own limit on bodies is 8 MB; inputs this large fuzz slowly, and the element limit
// is what a fuzzed mesh should reach.
constexpr std::int64_t kMaxElements = 5'000;

server::ServerOptions Options() {
  server::ServerOptions options;
  options.max_elements = kMaxElements;
  return options;
}

// Every error body must be JSON a browser can parse, whatever bytes the message quotes.
void CheckErrorBody(const absl::Status& status) {
  const std::string body = server::ErrorJson(status.code(), status.message());
  google::protobuf::Struct parsed;
  Check(google::protobuf::util::JsonStringToMessage(body, &parsed).ok(),
        absl::StrCat("the error body is not JSON: ", body));
  const auto code = parsed.fields().find("code");
  Check(code != parsed.fields().end() &&
            code->second.string_value() == absl::StatusCodeToString(status.code()) &&
            parsed.fields().count("message") == 1,
        absl::StrCat("the error body lacks its code or message: ", body));
}

}  // namespace
}  // namespace getme::fuzz

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace getme;
  static server::JobRegistry registry(/*max_queued_jobs=*/1, absl::Minutes(1));
  static const server::ServerOptions options = fuzz::Options();
  fuzz::QuietLogging();
  const std::string body(reinterpret_cast<const char*>(data), size);

  absl::StatusOr<std::shared_ptr<server::Job>> job =
      server::CreateJobFromJson(body, registry, options, /*metrics=*/nullptr);
  if (!fuzz::Accepted(job.status(), "POST /v1/jobs")) {
    fuzz::CheckErrorBody(job.status());
    return 0;
  }

  // An accepted body is a mesh the element limit allows, and the job says what it holds.
  v1::CreateJobRequest request;
  fuzz::CheckOk(server::FromJson(body, request), "FromJson of an accepted body");
  const v1::Job described = (*job)->Describe();
  fuzz::Check(
      static_cast<std::int64_t>(described.elements()) == wire::WireElementCount(request.mesh()) &&
          described.elements() <= static_cast<std::uint64_t>(fuzz::kMaxElements),
      "the job's element count is not the body's");
  fuzz::Check(static_cast<int>(described.nodes()) == request.mesh().coordinates_size() / 3,
              "the job's node count is not the body's");

  // What the gateway answers is canonical protobuf JSON: it reads back as the same message.
  v1::Job read_back;
  fuzz::CheckOk(server::FromJson(server::ToJson(described), read_back), "FromJson(ToJson(job))");
  fuzz::Check(google::protobuf::util::MessageDifferencer::Equals(described, read_back),
              "the job's JSON does not read back as the same job");
  v1::CreateJobRequest request_again;
  fuzz::CheckOk(server::FromJson(server::ToJson(request), request_again),
                "FromJson(ToJson(request))");
  fuzz::Check(google::protobuf::util::MessageDifferencer::Equals(request, request_again),
              "the request's JSON does not read back as the same request");
  return 0;
}
