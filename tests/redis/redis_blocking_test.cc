#include <gtest/gtest.h>

#include <thread>

#include "absl/strings/str_cat.h"
#include "absl/time/clock.h"
#include "redis/redis_client.h"
#include "redis_server_test.h"

namespace getme::redis::testing {
namespace {

using RedisBlockingTest = RedisServerTest;

TEST_F(RedisBlockingTest, BlpopTimesOutWithNil) {
  // A command timeout shorter than the wait: Blocking must raise it for the call.
  std::unique_ptr<RedisClient> client = ConnectClient(absl::Milliseconds(200));
  ASSERT_NE(client, nullptr);
  const absl::Time start = absl::Now();
  absl::StatusOr<RedisReply> popped =
      client->Blocking({"BLPOP", "queue", "0.5"}, absl::Milliseconds(500));
  const absl::Duration waited = absl::Now() - start;
  ASSERT_TRUE(popped.ok()) << popped.status();
  EXPECT_TRUE(popped->is_nil()) << popped->DebugString();
  EXPECT_GE(waited, absl::Milliseconds(450));
  EXPECT_LT(waited, absl::Seconds(3));
  // The connection went back to the pool with its short timeout again.
  absl::StatusOr<RedisReply> pong = client->Command({"PING"});
  ASSERT_TRUE(pong.ok()) << pong.status();
  EXPECT_EQ(client->open_connections(), 1);
  EXPECT_EQ(client->Command({"BLPOP", "queue", "1"}).status().code(),
            absl::StatusCode::kDeadlineExceeded);
}

TEST_F(RedisBlockingTest, BlpopIsWokenByAPushFromAnotherThread) {
  std::unique_ptr<RedisClient> client = ConnectClient();
  ASSERT_NE(client, nullptr);
  absl::StatusOr<RedisReply> popped;
  absl::Duration waited;
  std::thread waiter([&] {
    const absl::Time start = absl::Now();
    popped = client->Blocking({"BLPOP", "queue", "5"}, absl::Seconds(5));
    waited = absl::Now() - start;
  });
  // The pusher shares the client: the waiter holds one connection, the push takes another.
  const bool blocked = WaitForBlockedClients(*client, 1);
  absl::StatusOr<RedisReply> pushed = client->Command({"RPUSH", "queue", "job-7"});
  waiter.join();
  ASSERT_TRUE(blocked);
  ASSERT_TRUE(pushed.ok()) << pushed.status();
  ASSERT_TRUE(popped.ok()) << popped.status();
  EXPECT_EQ(*popped, RedisReply::Array({RedisReply::String("queue"), RedisReply::String("job-7")}));
  EXPECT_LT(waited, absl::Seconds(2));
  EXPECT_EQ(client->open_connections(), 2);
}

TEST_F(RedisBlockingTest, ACommandPastItsTimeoutIsDeadlineExceededAndTheClientGoesOn) {
  std::unique_ptr<RedisClient> client = ConnectClient(absl::Milliseconds(200));
  ASSERT_NE(client, nullptr);
  const absl::Status status = client->Command({"BLPOP", "queue", "0"}).status();
  EXPECT_EQ(status.code(), absl::StatusCode::kDeadlineExceeded) << status;
  EXPECT_EQ(status.message(), absl::StrCat("redis: BLPOP on redis://127.0.0.1:", server_->port(),
                                           "/0 timed out (Resource temporarily unavailable)"));
  // The timed-out connection was closed (its late reply must not answer another command).
  EXPECT_EQ(client->open_connections(), 0);
  absl::StatusOr<RedisReply> pong = client->Command({"PING"});
  ASSERT_TRUE(pong.ok()) << pong.status();
  EXPECT_EQ(pong->str(), "PONG");
}

}  // namespace
}  // namespace getme::redis::testing
