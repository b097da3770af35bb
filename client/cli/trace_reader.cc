#include "cli/trace_reader.h"

#include <fstream>

#include "absl/strings/str_cat.h"
#include "nlohmann/json.hpp"

namespace getme::cli {
namespace {

// The value of `key`, or an error naming it.
template <typename T>
absl::Status Field(const nlohmann::json& event, const char* key, T& value) {
  const auto found = event.find(key);
  if (found == event.end()) return absl::InvalidArgumentError(absl::StrCat("no field '", key, "'"));
  try {
    value = found->get<T>();
  } catch (const nlohmann::json::exception&) {
    return absl::InvalidArgumentError(absl::StrCat("field '", key, "' has the wrong type"));
  }
  return absl::OkStatus();
}

absl::Status ParsePoint(const nlohmann::json& event, TracePoint& point) {
  for (absl::Status status :
       {Field(event, "phase", point.phase), Field(event, "iteration", point.iteration),
        Field(event, "q_min", point.q_min), Field(event, "q_mean", point.q_mean),
        Field(event, "elapsed_seconds", point.elapsed_seconds),
        Field(event, "phase_done", point.phase_done)}) {
    if (!status.ok()) return status;
  }
  return absl::OkStatus();
}

}  // namespace

absl::StatusOr<std::vector<TracePoint>> ReadTrace(const std::string& path) {
  std::ifstream stream(path);
  if (!stream) {
    const int error = errno;
    return absl::ErrnoToStatus(error, absl::StrCat("cannot open the trace '", path, "'"));
  }
  std::vector<TracePoint> points;
  std::string line;
  for (std::int64_t number = 1; std::getline(stream, line); ++number) {
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    const nlohmann::json event = nlohmann::json::parse(line, nullptr, /*allow_exceptions=*/false);
    if (event.is_discarded() || !event.is_object()) {
      return absl::InvalidArgumentError(
          absl::StrCat(path, ":", number,
                       ": not a JSON object (expected the lines of 'getme "
                       "smooth --trace' or '--json')"));
    }
    const auto kind = event.find("event");
    if (kind == event.end() || !kind->is_string() || *kind != "progress") continue;
    TracePoint point;
    if (absl::Status status = ParsePoint(event, point); !status.ok()) {
      return absl::InvalidArgumentError(
          absl::StrCat(path, ":", number, ": progress event: ", status.message()));
    }
    points.push_back(std::move(point));
  }
  if (stream.bad()) {
    return absl::DataLossError(absl::StrCat("reading the trace '", path, "' failed"));
  }
  return points;
}

}  // namespace getme::cli
