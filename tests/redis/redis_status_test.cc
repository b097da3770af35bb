#include "redis/redis_status.h"

#include <gtest/gtest.h>
#include <hiredis/hiredis.h>

#include <cerrno>

#include "absl/strings/str_cat.h"

namespace getme::redis {
namespace {

TEST(StatusFromErrorReply, ACodeNameAndSpaceGiveThatCode) {
  const absl::Status status = StatusFromErrorReply("RESOURCE_EXHAUSTED the queue is full");
  EXPECT_EQ(status, absl::ResourceExhaustedError("the queue is full"));
}

TEST(StatusFromErrorReply, ACodeNameAndColonGiveThatCode) {
  EXPECT_EQ(StatusFromErrorReply("NOT_FOUND: job 12"), absl::NotFoundError("job 12"));
  EXPECT_EQ(StatusFromErrorReply("FAILED_PRECONDITION:job 12 is done"),
            absl::FailedPreconditionError("job 12 is done"));
  EXPECT_EQ(StatusFromErrorReply("ABORTED"), absl::AbortedError(""));
}

TEST(StatusFromErrorReply, EveryCodeNameIsKnown) {
  for (int number = 1; number <= 16; ++number) {
    const auto code = static_cast<absl::StatusCode>(number);
    const std::string text = absl::StrCat(absl::StatusCodeToString(code), " why");
    EXPECT_EQ(StatusFromErrorReply(text), absl::Status(code, "why")) << text;
  }
}

TEST(StatusFromErrorReply, StripsWhatRedis7AddsToScriptErrors) {
  // As redis-server 7.0 reports error("FAILED_PRECONDITION boom") and error({err=...}).
  EXPECT_EQ(StatusFromErrorReply("ERR user_script:1: FAILED_PRECONDITION boom script: "
                                 "7886188996d807ffa9e36925a509f40f8840c3f8, on @user_script:1."),
            absl::FailedPreconditionError("boom"));
  EXPECT_EQ(StatusFromErrorReply("ABORTED lost the lease script: "
                                 "0af43879c0545863f7715f882e44c39fbf7bb15b, on @user_script:12."),
            absl::AbortedError("lost the lease"));
}

TEST(StatusFromErrorReply, OtherErrorsAreInternalWithTheWholeText) {
  EXPECT_EQ(StatusFromErrorReply("WRONGTYPE Operation against a key holding the wrong kind"),
            absl::InternalError("redis: WRONGTYPE Operation against a key holding the wrong kind"));
  EXPECT_EQ(StatusFromErrorReply("ERR value is not an integer or out of range script: "
                                 "024f02195a7e52e1776d26af209f8a79d0470e0f, on @user_script:1."),
            absl::InternalError("redis: ERR value is not an integer or out of range script: "
                                "024f02195a7e52e1776d26af209f8a79d0470e0f, on @user_script:1."));
}

TEST(StatusFromErrorReply, AFullRedisIsResourceExhausted) {
  const absl::Status status =
      StatusFromErrorReply("OOM command not allowed when used memory > 'maxmemory'.");
  EXPECT_EQ(status.code(), absl::StatusCode::kResourceExhausted);
  EXPECT_EQ(status.message(), "redis: OOM command not allowed when used memory > 'maxmemory'.");
}

TEST(StatusFromErrorReply, ACodeNameMustBeAWholeWord) {
  EXPECT_EQ(StatusFromErrorReply("NOT_FOUNDING x"), absl::InternalError("redis: NOT_FOUNDING x"));
  EXPECT_EQ(StatusFromErrorReply("OK fine"), absl::InternalError("redis: OK fine"));
  EXPECT_EQ(StatusFromErrorReply("not_found x"), absl::InternalError("redis: not_found x"));
}

TEST(StatusFromConnectionError, SocketTimeoutsAreDeadlineExceeded) {
  EXPECT_EQ(StatusFromConnectionError(REDIS_ERR_IO, EAGAIN, "Resource temporarily unavailable",
                                      "GET on redis://h:6379/0"),
            absl::DeadlineExceededError(
                "redis: GET on redis://h:6379/0 timed out (Resource temporarily unavailable)"));
}

TEST(StatusFromConnectionError, OtherFailuresAreUnavailable) {
  EXPECT_EQ(StatusFromConnectionError(REDIS_ERR_EOF, 0, "Server closed the connection",
                                      "GET on redis://h:6379/0"),
            absl::UnavailableError(
                "redis: GET on redis://h:6379/0 failed: Server closed the connection"));
  EXPECT_EQ(StatusFromConnectionError(REDIS_ERR_IO, ECONNRESET, "Connection reset by peer", "x"),
            absl::UnavailableError("redis: x failed: Connection reset by peer"));
  // TCP keepalive giving up on a vanished server during a long BLPOP.
  EXPECT_EQ(StatusFromConnectionError(REDIS_ERR_IO, ETIMEDOUT, "Connection timed out", "x"),
            absl::UnavailableError("redis: x failed: Connection timed out"));
}

}  // namespace
}  // namespace getme::redis
