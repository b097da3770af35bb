#include <gtest/gtest.h>

#include <thread>

#include "absl/strings/match.h"
#include "absl/strings/str_cat.h"
#include "absl/time/clock.h"
#include "redis/redis_client.h"
#include "redis_server_test.h"

namespace getme::redis::testing {
namespace {

// Every failure over a plain connection (false) and over TLS (true): the TLS transport has its
// own reads and writes (redis_tls.h), which must fail the same way.
class RedisFailureTest : public RedisServerTest, public ::testing::WithParamInterface<bool> {
 protected:
  RedisServerProcess::Options ServerOptions() const override {
    return GetParam() ? TlsServerOptions(/*require_client_certificate=*/false)
                      : RedisServerProcess::Options();
  }
};

INSTANTIATE_TEST_SUITE_P(PlainAndTls, RedisFailureTest, ::testing::Values(false, true),
                         [](const ::testing::TestParamInfo<bool>& info) {
                           return info.param ? "tls" : "plain";
                         });

TEST_P(RedisFailureTest, ConnectingToNoServerIsUnavailable) {
  RedisAddress address = Address();
  server_->Kill();
  absl::StatusOr<std::unique_ptr<RedisClient>> client =
      RedisClient::Connect(address, absl::Seconds(1));
  EXPECT_EQ(client.status(),
            absl::UnavailableError(absl::StrCat("redis: cannot connect to ", RedactedUrl(address),
                                                ": Connection refused")));
}

TEST_P(RedisFailureTest, AKilledServerIsUnavailableAndARestartedOneServesAgain) {
  std::unique_ptr<RedisClient> client = ConnectClient();
  ASSERT_NE(client, nullptr);
  ASSERT_TRUE(client->Command({"SET", "k", "v"}).ok());
  server_->Kill();

  const absl::Status lost = client->Command({"GET", "k"}).status();
  EXPECT_EQ(lost.code(), absl::StatusCode::kUnavailable) << lost;
  EXPECT_TRUE(absl::StrContains(lost.message(), RedactedUrl(Address()))) << lost;
  EXPECT_EQ(client->open_connections(), 0);
  // Nothing listens: connecting afresh fails too, and says so.
  EXPECT_EQ(client->Command({"GET", "k"}).status(),
            absl::UnavailableError(absl::StrCat("redis: cannot connect to ", RedactedUrl(Address()),
                                                ": Connection refused")));

  ASSERT_TRUE(server_->Restart().ok());
  absl::StatusOr<RedisReply> after = client->Command({"GET", "k"});
  ASSERT_TRUE(after.ok()) << after.status();
  EXPECT_TRUE(after->is_nil());  // --save "": the restarted server starts empty
  EXPECT_TRUE(client->Command({"SET", "k", "again"}).ok());
}

TEST_P(RedisFailureTest, AKilledServerClosesEveryIdleConnection) {
  std::unique_ptr<RedisClient> client = ConnectClient();
  ASSERT_NE(client, nullptr);
  // Two connections in the pool: one held by a BLPOP while another pings.
  std::thread waiter([&] { (void)client->Blocking({"BLPOP", "queue", "10"}, absl::Seconds(10)); });
  const bool blocked = WaitForBlockedClients(*client, 1);
  const bool pinged = client->Command({"PING"}).ok();
  (void)client->Command({"RPUSH", "queue", "wake"});  // ends the BLPOP
  waiter.join();
  ASSERT_TRUE(blocked);
  ASSERT_TRUE(pinged);
  ASSERT_EQ(client->open_connections(), 2);

  server_->Kill();
  ASSERT_TRUE(server_->Restart().ok());
  // One call pays for the restart; it closes the other stale connection with its own.
  EXPECT_EQ(client->Command({"PING"}).status().code(), absl::StatusCode::kUnavailable);
  EXPECT_EQ(client->open_connections(), 0);
  absl::StatusOr<RedisReply> pong = client->Command({"PING"});
  ASSERT_TRUE(pong.ok()) << pong.status();
  EXPECT_EQ(pong->str(), "PONG");
}

}  // namespace
}  // namespace getme::redis::testing
