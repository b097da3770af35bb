#include <gtest/gtest.h>

#include <thread>
#include <vector>

#include "redis/redis_client.h"
#include "redis_server_test.h"

namespace getme::redis::testing {
namespace {

using RedisConcurrencyTest = RedisServerTest;

TEST_F(RedisConcurrencyTest, EightThreadsShareOneClient) {
  std::unique_ptr<RedisClient> client = ConnectClient();
  ASSERT_NE(client, nullptr);
  constexpr int kThreads = 8;
  constexpr int kIncrementsEach = 200;
  static const RedisScript kAddAndRead("return redis.call('INCRBY', KEYS[1], ARGV[1])");
  std::vector<int> failures(kThreads, 0);
  std::vector<std::thread> threads;
  for (int t = 0; t < kThreads; ++t) {
    threads.emplace_back([&, t] {
      for (int i = 0; i < kIncrementsEach; ++i) {
        // Plain commands, pipelines and scripts interleave on the pooled connections.
        bool ok = false;
        switch (i % 4) {
          case 0:
          case 1:
            ok = client->Command({"INCR", "counter"}).ok();
            break;
          case 2:
            ok = client->Pipeline({{"INCR", "counter"}, {"GET", "counter"}}).ok();
            break;
          case 3:
            ok = client->Eval(kAddAndRead, {"counter"}, {"1"}).ok();
            break;
        }
        if (!ok) ++failures[t];
      }
    });
  }
  for (std::thread& thread : threads) thread.join();
  for (int t = 0; t < kThreads; ++t) EXPECT_EQ(failures[t], 0) << "thread " << t;
  absl::StatusOr<RedisReply> counter = client->Command({"GET", "counter"});
  ASSERT_TRUE(counter.ok()) << counter.status();
  EXPECT_EQ(counter->str(), "1600");
  EXPECT_GE(client->open_connections(), 1);
  EXPECT_LE(client->open_connections(), kThreads);
}

}  // namespace
}  // namespace getme::redis::testing
