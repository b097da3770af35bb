#include "redis/redis_client.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "absl/strings/match.h"
#include "absl/strings/str_cat.h"
#include "redis_server_test.h"

namespace getme::redis::testing {
namespace {

using Type = RedisReply::Type;
using RedisClientTest = RedisServerTest;

TEST_F(RedisClientTest, SetAndGetAString) {
  std::unique_ptr<RedisClient> client = ConnectClient();
  ASSERT_NE(client, nullptr);
  absl::StatusOr<RedisReply> set = client->Command({"SET", "greeting", "hello"});
  ASSERT_TRUE(set.ok()) << set.status();
  EXPECT_EQ(*set, RedisReply::Status("OK"));
  absl::StatusOr<RedisReply> get = client->Command(std::vector<std::string>{"GET", "greeting"});
  ASSERT_TRUE(get.ok()) << get.status();
  EXPECT_EQ(get->type(), Type::kString);
  EXPECT_EQ(get->str(), "hello");
}

TEST_F(RedisClientTest, RepliesOfEveryType) {
  std::unique_ptr<RedisClient> client = ConnectClient();
  ASSERT_NE(client, nullptr);
  absl::StatusOr<RedisReply> missing = client->Command({"GET", "nothing-here"});
  ASSERT_TRUE(missing.ok()) << missing.status();
  EXPECT_TRUE(missing->is_nil());
  absl::StatusOr<RedisReply> counter = client->Command({"INCRBY", "counter", "-5"});
  ASSERT_TRUE(counter.ok()) << counter.status();
  EXPECT_EQ(counter->type(), Type::kInteger);
  EXPECT_EQ(counter->integer(), -5);
  ASSERT_TRUE(client->Command({"RPUSH", "list", "a", "b"}).ok());
  absl::StatusOr<RedisReply> list = client->Command({"LRANGE", "list", "0", "-1"});
  ASSERT_TRUE(list.ok()) << list.status();
  EXPECT_EQ(*list, RedisReply::Array({RedisReply::String("a"), RedisReply::String("b")}));
  absl::StatusOr<RedisReply> values = client->Command({"MGET", "list-missing", "counter"});
  ASSERT_TRUE(values.ok()) << values.status();
  EXPECT_EQ(values->DebugString(), "[nil, \"-5\"]");
}

TEST_F(RedisClientTest, ValuesWithNulBytesRoundTrip) {
  std::unique_ptr<RedisClient> client = ConnectClient();
  ASSERT_NE(client, nullptr);
  const std::string key("job\0:1", 6);
  const std::string value("\0\x01\xff\r\n$3\r\n\0", 11);
  ASSERT_TRUE(client->Command({"SET", key, value}).ok());
  absl::StatusOr<RedisReply> get = client->Command({"GET", key});
  ASSERT_TRUE(get.ok()) << get.status();
  EXPECT_EQ(get->str(), value);
  absl::StatusOr<RedisReply> wrong_key = client->Command({"GET", "job"});
  ASSERT_TRUE(wrong_key.ok());
  EXPECT_TRUE(wrong_key->is_nil());
}

TEST_F(RedisClientTest, AMegabyteValueRoundTrips) {
  std::unique_ptr<RedisClient> client = ConnectClient();
  ASSERT_NE(client, nullptr);
  std::string value(1 << 20, '\0');
  for (size_t i = 0; i < value.size(); ++i) value[i] = static_cast<char>(i * 131 % 256);
  ASSERT_TRUE(client->Command({"SET", "result", value}).ok());
  absl::StatusOr<RedisReply> get = client->Command({"GET", "result"});
  ASSERT_TRUE(get.ok()) << get.status();
  EXPECT_EQ(get->str().size(), value.size());
  EXPECT_TRUE(get->str() == value);
  absl::StatusOr<RedisReply> length = client->Command({"STRLEN", "result"});
  ASSERT_TRUE(length.ok());
  EXPECT_EQ(length->integer(), 1 << 20);
}

TEST_F(RedisClientTest, ErrorRepliesAreInternal) {
  std::unique_ptr<RedisClient> client = ConnectClient();
  ASSERT_NE(client, nullptr);
  ASSERT_TRUE(client->Command({"SET", "text", "abc"}).ok());
  EXPECT_EQ(client->Command({"INCR", "text"}).status(),
            absl::InternalError("redis: ERR value is not an integer or out of range"));
  EXPECT_EQ(client->Command({"NOSUCHCOMMAND"}).status().code(), absl::StatusCode::kInternal);
  // An error reply leaves the connection in step: the next command gets its own reply.
  absl::StatusOr<RedisReply> get = client->Command({"GET", "text"});
  ASSERT_TRUE(get.ok()) << get.status();
  EXPECT_EQ(get->str(), "abc");
  EXPECT_EQ(client->open_connections(), 1);
}

TEST_F(RedisClientTest, AnEmptyCommandIsRefused) {
  std::unique_ptr<RedisClient> client = ConnectClient();
  ASSERT_NE(client, nullptr);
  EXPECT_EQ(client->Command(std::vector<std::string>{}).status(),
            absl::InvalidArgumentError("redis: a command without arguments"));
  EXPECT_EQ(client->Pipeline({{"PING"}, {}}).status(),
            absl::InvalidArgumentError("redis: a command without arguments"));
}

TEST_F(RedisClientTest, PipelineRepliesComeInOrder) {
  std::unique_ptr<RedisClient> client = ConnectClient();
  ASSERT_NE(client, nullptr);
  absl::StatusOr<std::vector<RedisReply>> replies = client->Pipeline({
      {"SET", "a", "1"},
      {"INCR", "a"},
      {"GET", "a"},
      {"GET", "missing"},
      {"RPUSH", "q", "x", "y"},
  });
  ASSERT_TRUE(replies.ok()) << replies.status();
  EXPECT_EQ(*replies, (std::vector<RedisReply>{RedisReply::Status("OK"), RedisReply::Integer(2),
                                               RedisReply::String("2"), RedisReply::Nil(),
                                               RedisReply::Integer(2)}));
  absl::StatusOr<std::vector<RedisReply>> none = client->Pipeline({});
  ASSERT_TRUE(none.ok());
  EXPECT_TRUE(none->empty());
}

TEST_F(RedisClientTest, APipelineFailsOnItsFirstErrorButRunsEveryCommand) {
  std::unique_ptr<RedisClient> client = ConnectClient();
  ASSERT_NE(client, nullptr);
  absl::StatusOr<std::vector<RedisReply>> replies = client->Pipeline({
      {"SET", "text", "abc"},
      {"INCR", "text"},
      {"LPUSH", "text", "x"},
      {"SET", "after", "ran"},
  });
  EXPECT_EQ(replies.status(),
            absl::InternalError("redis: ERR value is not an integer or out of range"));
  // Not a transaction: the commands after the error ran, and the connection is still in step.
  absl::StatusOr<RedisReply> after = client->Command({"GET", "after"});
  ASSERT_TRUE(after.ok()) << after.status();
  EXPECT_EQ(after->str(), "ran");
}

TEST_F(RedisClientTest, ErrorsInsideATransactionAreArrayElements) {
  std::unique_ptr<RedisClient> client = ConnectClient();
  ASSERT_NE(client, nullptr);
  absl::StatusOr<std::vector<RedisReply>> replies = client->Pipeline({
      {"MULTI"},
      {"SET", "text", "abc"},
      {"INCR", "text"},
      {"EXEC"},
  });
  ASSERT_TRUE(replies.ok()) << replies.status();
  ASSERT_EQ(replies->size(), 4u);
  const RedisReply& exec = replies->back();
  ASSERT_EQ(exec.elements().size(), 2u);
  EXPECT_EQ(exec.elements()[0], RedisReply::Status("OK"));
  EXPECT_EQ(exec.elements()[1].type(), Type::kError);
  EXPECT_EQ(exec.elements()[1].str(), "ERR value is not an integer or out of range");
}

TEST_F(RedisClientTest, SelectsTheUrlsDatabase) {
  std::unique_ptr<RedisClient> default_db = ConnectClient();
  ASSERT_NE(default_db, nullptr);
  RedisAddress address = Address();
  address.db = 5;
  absl::StatusOr<std::unique_ptr<RedisClient>> db5 = RedisClient::Connect(address);
  ASSERT_TRUE(db5.ok()) << db5.status();
  ASSERT_TRUE((*db5)->Command({"SET", "where", "five"}).ok());
  absl::StatusOr<RedisReply> in_db0 = default_db->Command({"GET", "where"});
  ASSERT_TRUE(in_db0.ok());
  EXPECT_TRUE(in_db0->is_nil());
  absl::StatusOr<RedisReply> info = (*db5)->Command({"CLIENT", "INFO"});
  ASSERT_TRUE(info.ok()) << info.status();
  EXPECT_TRUE(absl::StrContains(info->str(), " db=5 ")) << info->str();
}

TEST_F(RedisClientTest, ADatabaseThatDoesNotExistIsRefused) {
  RedisAddress address = Address();
  address.db = 99;  // redis-server has 16 databases unless configured otherwise
  absl::StatusOr<std::unique_ptr<RedisClient>> client = RedisClient::Connect(address);
  EXPECT_EQ(client.status(),
            absl::InvalidArgumentError(absl::StrCat("redis: SELECT 99 on ", RedactedUrl(address),
                                                    " refused: ERR DB index is out of range")));
}

TEST_F(RedisClientTest, ReusesItsConnection) {
  std::unique_ptr<RedisClient> client = ConnectClient();
  ASSERT_NE(client, nullptr);
  for (int i = 0; i < 20; ++i) ASSERT_TRUE(client->Command({"PING"}).ok());
  EXPECT_EQ(client->open_connections(), 1);
  absl::StatusOr<RedisReply> clients = client->Command({"CLIENT", "LIST"});
  ASSERT_TRUE(clients.ok());
  EXPECT_EQ(std::count(clients->str().begin(), clients->str().end(), '\n'), 1);
}

}  // namespace
}  // namespace getme::redis::testing
