// A Smooth call's own result does not expire under it: the registry holds the result of a job
// whose submitter fetches it (ResultHold) past --result_ttl, and only while held. The CI once lost
// a Smooth result this way: a loaded machine woke the call more than a 200 ms TTL after its job
// ended.
#include <memory>
#include <string>
#include <utility>

#include "absl/status/status.h"
#include "absl/time/clock.h"
#include "getme_server/job.h"
#include "getme_server/job_directory.h"
#include "getme_server/job_registry.h"
#include "getme_wire/mesh_upload.h"
#include "gtest/gtest.h"
#include "server_test_support.h"

namespace getme::server::testing {
namespace {

wire::UploadedMesh SmallUpload() {
  absl::StatusOr<wire::UploadedMesh> mesh = wire::ToEngineMesh(ToWire(TetBlock(2, 0.2)), 1000);
  EXPECT_TRUE(mesh.ok()) << mesh.status();
  return *std::move(mesh);
}

std::shared_ptr<Job> FinishedJob(ResultHold* hold) {
  auto job = std::make_shared<Job>("held", SmallUpload(), 1, SmoothingParams{}, v1::ResultOptions{},
                                   absl::Milliseconds(100));
  if (hold != nullptr) *hold = job->HoldResult();
  job->Run(absl::Now());
  EXPECT_EQ(job->state(), v1::JOB_STATE_SUCCEEDED) << job->outcome();
  return job;
}

TEST(ResultHoldTest, AHeldResultOutlivesItsTimeToLive) {
  ResultHold hold;
  std::shared_ptr<Job> job = FinishedJob(&hold);
  // An hour after the end with a 1 ms time to live: neither expired nor forgotten.
  EXPECT_FALSE(job->ExpireIfOlderThan(absl::Now() + absl::Hours(1), absl::Milliseconds(1)));
  EXPECT_TRUE(job->Describe().result_available());
  EXPECT_TRUE(job->TakeResult().ok());
}

TEST(ResultHoldTest, TheResultExpiresOnceTheHoldIsReleased) {
  ResultHold hold;
  std::shared_ptr<Job> job = FinishedJob(&hold);
  ResultHold moved = std::move(hold);  // still held: the moved-from hold releases nothing
  hold = ResultHold();
  EXPECT_FALSE(job->ExpireIfOlderThan(absl::Now() + absl::Hours(1), absl::Milliseconds(1)));
  moved = ResultHold();
  EXPECT_TRUE(job->ExpireIfOlderThan(absl::Now() + absl::Hours(1), absl::Milliseconds(1)));
  absl::StatusOr<JobResult> result = job->TakeResult();
  EXPECT_EQ(result.status().code(), absl::StatusCode::kNotFound);
  EXPECT_NE(result.status().message().find("its time to live passed"), std::string::npos)
      << result.status();
}

TEST(ResultHoldTest, AnUnheldResultExpiresAfterItsTimeToLive) {
  std::shared_ptr<Job> job = FinishedJob(nullptr);
  EXPECT_FALSE(job->ExpireIfOlderThan(absl::Now(), absl::Hours(1)));  // not yet
  EXPECT_TRUE(job->ExpireIfOlderThan(absl::Now() + absl::Hours(1), absl::Milliseconds(1)));
  EXPECT_FALSE(job->Describe().result_available());
}

// Through the registry and its sweeper (every 10 ms at a 1 ms time to live): only the submission
// whose submitter fetches the result is held, and for as long as its SubmittedJob lives.
TEST(ResultHoldTest, TheRegistryHoldsOnlyWhatTheSubmitterFetches) {
  JobRegistry registry(/*max_queued_jobs=*/4, /*result_ttl=*/absl::Milliseconds(1));
  auto submit = [&](bool fetched_by_submitter) {
    JobSubmission submission;
    submission.mesh = SmallUpload();
    submission.submitter_fetches_result = fetched_by_submitter;
    absl::StatusOr<SubmittedJob> submitted = registry.Submit(std::move(submission), "");
    EXPECT_TRUE(submitted.ok()) << submitted.status();
    std::shared_ptr<Job> job = registry.TakeNextQueued();
    job->Run(absl::Now());
    return *std::move(submitted);
  };
  SubmittedJob held = submit(true);
  const std::string unheld_id = submit(false).job->id();
  auto forgotten = [&](const std::string& id) {
    for (int wait = 0; wait < 1000; ++wait) {
      if (!registry.Find(id, "").ok()) return true;
      absl::SleepFor(absl::Milliseconds(10));
    }
    return false;
  };
  ASSERT_TRUE(forgotten(unheld_id)) << "the unheld job was never forgotten";
  // The sweeper passed the held job many times by now (twice the TTL is 2 ms).
  absl::SleepFor(absl::Milliseconds(100));
  EXPECT_TRUE(held.job->Describe().result_available());
  absl::StatusOr<std::unique_ptr<ResultStream>> stream = held.job->TakeResultStream();
  ASSERT_TRUE(stream.ok()) << stream.status();
  (*stream)->GiveBack();
  const std::string held_id = held.job->id();
  held = SubmittedJob();  // the call returned
  EXPECT_TRUE(forgotten(held_id)) << "the job was never forgotten after its hold went";
}

}  // namespace
}  // namespace getme::server::testing
