#include <gtest/gtest.h>

#include "absl/strings/str_cat.h"
#include "redis/redis_client.h"
#include "redis_server_test.h"

namespace getme::redis::testing {
namespace {

class RedisAuthTest : public RedisServerTest {
 protected:
  RedisServerProcess::Options ServerOptions() const override {
    RedisServerProcess::Options options;
    options.password = "s3cret";
    return options;
  }
};

TEST_F(RedisAuthTest, TheRightPasswordLogsIn) {
  std::unique_ptr<RedisClient> client = ConnectClient();
  ASSERT_NE(client, nullptr);
  absl::StatusOr<RedisReply> who = client->Command({"ACL", "WHOAMI"});
  ASSERT_TRUE(who.ok()) << who.status();
  EXPECT_EQ(who->str(), "default");
}

TEST_F(RedisAuthTest, AWrongPasswordIsUnauthenticated) {
  RedisAddress address = Address();
  address.password = "guess";
  absl::StatusOr<std::unique_ptr<RedisClient>> client = RedisClient::Connect(address);
  EXPECT_EQ(client.status(),
            absl::UnauthenticatedError(absl::StrCat(
                "redis: AUTH on redis://:***@127.0.0.1:", server_->port(),
                "/0 refused: WRONGPASS invalid username-password pair or user is disabled.")));
  EXPECT_EQ(client.status().message().find("guess"), absl::string_view::npos);
}

TEST_F(RedisAuthTest, NoPasswordIsUnauthenticated) {
  RedisAddress address = Address();
  address.password.clear();
  absl::StatusOr<std::unique_ptr<RedisClient>> client = RedisClient::Connect(address);
  EXPECT_EQ(client.status(), absl::UnauthenticatedError(
                                 absl::StrCat("redis: PING on redis://127.0.0.1:", server_->port(),
                                              "/0 refused: NOAUTH Authentication required.")));
}

TEST_F(RedisAuthTest, AnAclUserLogsInWithUserAndPassword) {
  std::unique_ptr<RedisClient> admin = ConnectClient();
  ASSERT_NE(admin, nullptr);
  ASSERT_TRUE(
      admin->Command({"ACL", "SETUSER", "getme", "on", ">pw-of-getme", "~*", "+@all"}).ok());
  RedisAddress address = Address();
  address.user = "getme";
  address.password = "pw-of-getme";
  absl::StatusOr<std::unique_ptr<RedisClient>> client = RedisClient::Connect(address);
  ASSERT_TRUE(client.ok()) << client.status();
  absl::StatusOr<RedisReply> who = (*client)->Command({"ACL", "WHOAMI"});
  ASSERT_TRUE(who.ok()) << who.status();
  EXPECT_EQ(who->str(), "getme");

  address.password = "s3cret";  // the default user's password is not getme's
  EXPECT_EQ(RedisClient::Connect(address).status().code(), absl::StatusCode::kUnauthenticated);
}

}  // namespace
}  // namespace getme::redis::testing
