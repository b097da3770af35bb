#include "getme_server/job_result_stream.h"

#include <utility>

namespace getme::server {

JobResultStream::JobResultStream(JobResult result, std::function<void(JobResult)> give_back)
    : result_(std::make_unique<JobResult>(std::move(result))),
      give_back_(std::move(give_back)),
      chunker_(result_->mesh, result_->ids, result_->options.coordinates_only(),
               wire::ResultChunkLimits(result_->options.nodes_per_chunk())) {}

bool JobResultStream::Next(v1::SmoothResponse& message) {
  if (!summary_sent_) {
    summary_sent_ = true;
    *message.mutable_result() = result_->summary;
    return true;
  }
  return chunker_.Next(*message.mutable_chunk());
}

void JobResultStream::GiveBack() {
  if (give_back_ != nullptr && result_ != nullptr) give_back_(std::move(*result_));
  give_back_ = nullptr;
}

}  // namespace getme::server
