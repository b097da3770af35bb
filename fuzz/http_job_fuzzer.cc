// libFuzzer target: the body of the HTTP gateway's POST /v1/jobs, through the same function the
// endpoint calls (SubmissionFromJson: protobuf JSON, then the checks every front end shares). The
// job is created but not queued, so no engine runs.
#include <cstddef>
#include <cstdint>
#include <string>

#include "absl/strings/str_cat.h"
#include "fuzz_check.h"
#include "getme/v1/smoother.pb.h"
#include "getme_server/http_json.h"
#include "getme_server/job.h"
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
  static const server::ServerOptions options = fuzz::Options();
  fuzz::QuietLogging();
  const std::string body(reinterpret_cast<const char*>(data), size);

  absl::StatusOr<server::JobSubmission> submission =
      server::SubmissionFromJson(body, options, /*keep_upload=*/true);
  if (!fuzz::Accepted(submission.status(), "POST /v1/jobs")) {
    fuzz::CheckErrorBody(submission.status());
    return 0;
  }
  // What a shared job store hands to another replica is the body's mesh, byte for byte.
  v1::Mesh kept;
  fuzz::Check(kept.ParseFromString(submission->received.whole_mesh),
              "the kept upload does not parse as a mesh");

  // An accepted body is a mesh the element limit allows, and the job says what it holds.
  v1::CreateJobRequest request;
  fuzz::CheckOk(server::FromJson(body, request), "FromJson of an accepted body");
  fuzz::Check(google::protobuf::util::MessageDifferencer::Equals(kept, request.mesh()),
              "the kept upload is not the body's mesh");
  const server::Job job("fuzz", std::move(submission->mesh), submission->upload_bytes,
                        submission->params, submission->header.result_options(),
                        options.progress_interval);
  const v1::Job described = job.Describe();
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
