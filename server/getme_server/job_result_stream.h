#pragma once

#include <functional>
#include <memory>

#include "getme_server/job_handle.h"
#include "getme_server/job_run.h"
#include "getme_wire/mesh_chunker.h"

namespace getme::server {

// A result held in this process as GetResult sends it: the summary, then the mesh cut by the
// caller's result options (coordinates only, nodes per chunk). GiveBack hands the JobResult to
// `give_back` (the job keeps it for another fetch).
class JobResultStream : public ResultStream {
 public:
  JobResultStream(JobResult result, std::function<void(JobResult)> give_back);

  bool Next(v1::SmoothResponse& message) override;
  void GiveBack() override;

 private:
  std::unique_ptr<JobResult> result_;  // stable address: the chunker reads its mesh and ids
  std::function<void(JobResult)> give_back_;
  wire::MeshChunker chunker_;
  bool summary_sent_ = false;
};

}  // namespace getme::server
