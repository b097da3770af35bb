#include "redis/redis_script.h"

#include <gtest/gtest.h>

#include "absl/strings/match.h"
#include "redis/redis_client.h"
#include "redis_server_test.h"

namespace getme::redis::testing {
namespace {

TEST(RedisScript, NamesTheSourceByItsSha1) {
  // sha1("return 1"), as `redis-cli SCRIPT LOAD "return 1"` answers.
  EXPECT_EQ(RedisScript("return 1").sha1(), "e0e1f9fabfc9d4800c877a703b823ac0578ff8db");
  EXPECT_EQ(RedisScript("return 1").source(), "return 1");
}

using RedisEvalTest = RedisServerTest;

TEST_F(RedisEvalTest, RunsAScriptWithKeysAndArguments) {
  std::unique_ptr<RedisClient> client = ConnectClient();
  ASSERT_NE(client, nullptr);
  static const RedisScript kSetAndCount(
      "redis.call('SET', KEYS[1], ARGV[1]) return {redis.call('STRLEN', KEYS[1]), ARGV[2]}");
  absl::StatusOr<RedisReply> reply =
      client->Eval(kSetAndCount, {"job:1"}, {std::string("a\0b", 3), "second"});
  ASSERT_TRUE(reply.ok()) << reply.status();
  EXPECT_EQ(*reply, RedisReply::Array({RedisReply::Integer(3), RedisReply::String("second")}));
  absl::StatusOr<RedisReply> stored = client->Command({"GET", "job:1"});
  ASSERT_TRUE(stored.ok());
  EXPECT_EQ(stored->str(), std::string("a\0b", 3));
}

TEST_F(RedisEvalTest, LoadsTheScriptAfterScriptFlush) {
  std::unique_ptr<RedisClient> client = ConnectClient();
  ASSERT_NE(client, nullptr);
  const RedisScript script("return redis.call('INCR', KEYS[1])");
  // The first call finds no script on the new server: NOSCRIPT, load, run.
  absl::StatusOr<RedisReply> first = client->Eval(script, {"n"}, {});
  ASSERT_TRUE(first.ok()) << first.status();
  EXPECT_EQ(first->integer(), 1);
  absl::StatusOr<RedisReply> exists = client->Command({"SCRIPT", "EXISTS", script.sha1()});
  ASSERT_TRUE(exists.ok());
  EXPECT_EQ(*exists, RedisReply::Array({RedisReply::Integer(1)}));

  ASSERT_TRUE(client->Command({"SCRIPT", "FLUSH"}).ok());
  absl::StatusOr<RedisReply> after_flush = client->Eval(script, {"n"}, {});
  ASSERT_TRUE(after_flush.ok()) << after_flush.status();
  EXPECT_EQ(after_flush->integer(), 2);  // ran exactly once more
  absl::StatusOr<RedisReply> value = client->Command({"GET", "n"});
  ASSERT_TRUE(value.ok());
  EXPECT_EQ(value->str(), "2");
}

TEST_F(RedisEvalTest, ErrorReplyNamesTheStatusCode) {
  std::unique_ptr<RedisClient> client = ConnectClient();
  ASSERT_NE(client, nullptr);
  const RedisScript full("return redis.error_reply('RESOURCE_EXHAUSTED the queue is full')");
  EXPECT_EQ(client->Eval(full, {}, {}).status(), absl::ResourceExhaustedError("the queue is full"));
  const RedisScript missing("return {err = 'NOT_FOUND: job ' .. ARGV[1]}");
  EXPECT_EQ(client->Eval(missing, {}, {"12"}).status(), absl::NotFoundError("job 12"));
  const RedisScript raised("error('FAILED_PRECONDITION job 12 is done')");
  EXPECT_EQ(client->Eval(raised, {}, {}).status(), absl::FailedPreconditionError("job 12 is done"));
  const RedisScript raised_table("error({err = 'ABORTED lease lost'})");
  EXPECT_EQ(client->Eval(raised_table, {}, {}).status(), absl::AbortedError("lease lost"));
}

TEST_F(RedisEvalTest, OtherScriptErrorsAreInternal) {
  std::unique_ptr<RedisClient> client = ConnectClient();
  ASSERT_NE(client, nullptr);
  const RedisScript wrong_type(
      "redis.call('SET', KEYS[1], 'x') return redis.call('INCR', KEYS[1])");
  const absl::Status status = client->Eval(wrong_type, {"k"}, {}).status();
  EXPECT_EQ(status.code(), absl::StatusCode::kInternal);
  EXPECT_TRUE(absl::StartsWith(status.message(),
                               "redis: ERR value is not an integer or out of range script: "))
      << status;
  const RedisScript syntax_error("return (");
  EXPECT_EQ(client->Eval(syntax_error, {}, {}).status().code(), absl::StatusCode::kInternal);
  // Neither left the connection out of step.
  absl::StatusOr<RedisReply> pong = client->Command({"PING"});
  ASSERT_TRUE(pong.ok());
  EXPECT_EQ(pong->str(), "PONG");
}

}  // namespace
}  // namespace getme::redis::testing
