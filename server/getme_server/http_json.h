#pragma once

#include <string>

#include "absl/status/status.h"
#include "absl/strings/string_view.h"
#include "google/protobuf/message.h"

namespace getme::server {

// The HTTP gateway's side of the wire: protobuf's canonical JSON mapping (lowerCamelCase field
// names, enums by name, 64-bit integers as strings), so JSON documents match the .proto files.

// Every field, defaults included, so browsers need not know the proto's defaults.
std::string ToJson(const google::protobuf::Message& message);
// INVALID_ARGUMENT naming the offending field (or the JSON syntax error); unknown fields are
// refused rather than silently dropped.
absl::Status FromJson(const std::string& json, google::protobuf::Message& message);

// The HTTP status for a canonical code, as grpc-gateway maps them (e.g. NOT_FOUND 404,
// INVALID_ARGUMENT 400, RESOURCE_EXHAUSTED 429, UNAVAILABLE 503).
int HttpStatusFromCode(absl::StatusCode code);
// {"code": "NOT_FOUND", "message": "..."}: the body of every error response.
std::string ErrorJson(absl::StatusCode code, absl::string_view message);

}  // namespace getme::server
