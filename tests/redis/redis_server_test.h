#pragma once

#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "absl/strings/match.h"
#include "absl/strings/str_cat.h"
#include "absl/time/clock.h"
#include "redis/redis_address.h"
#include "redis/redis_client.h"
#include "redis_server_process.h"
#include "test_certificates.h"

namespace getme::redis::testing {

// A server listening on a TLS port only, with the test certificates (tests/server): its
// certificate names IP 127.0.0.1 and DNS localhost, signed by the test CA, which also signs the
// client certificates it accepts (required when `require_client_certificate`).
inline RedisServerProcess::Options TlsServerOptions(bool require_client_certificate) {
  const server::testing::TestCertificates& certificates = server::testing::GetTestCertificates();
  RedisServerProcess::Options options;
  options.tls =
      RedisServerProcess::Options::Tls{.cert_file = certificates.server_cert,
                                       .key_file = certificates.server_key,
                                       .ca_file = certificates.ca_cert,
                                       .require_client_certificate = require_client_certificate};
  return options;
}

// A fixture with its own redis-server (skipped where redis-server is not installed) and helpers
// to connect to it.
class RedisServerTest : public ::testing::Test {
 protected:
  virtual RedisServerProcess::Options ServerOptions() const { return {}; }

  void SetUp() override {
    if (!RedisServerProcess::Available()) {
      GTEST_SKIP() << RedisServerProcess::kBinary
                   << " is not installed (apt-get install redis-server)";
    }
    absl::StatusOr<std::unique_ptr<RedisServerProcess>> server =
        RedisServerProcess::Start(ServerOptions());
    ASSERT_TRUE(server.ok()) << server.status();
    server_ = *std::move(server);
  }

  RedisAddress Address() const {
    absl::StatusOr<RedisAddress> address = ParseRedisUrl(server_->url());
    EXPECT_TRUE(address.ok()) << address.status();
    return address.value_or(RedisAddress());
  }

  // A client of the fixture's server; fails the test if it cannot connect.
  std::unique_ptr<RedisClient> ConnectClient(absl::Duration command_timeout = absl::Seconds(10)) {
    absl::StatusOr<std::unique_ptr<RedisClient>> client =
        RedisClient::Connect(Address(), absl::Seconds(5), command_timeout);
    EXPECT_TRUE(client.ok()) << client.status();
    return client.ok() ? *std::move(client) : nullptr;
  }

  // Waits, 10 s at most, until the server reports `count` clients blocked (in BLPOP, say): a
  // thread told to block has then really taken a connection of its own. `client` polls with
  // connections of its pool, which the blocked thread does not hold.
  static bool WaitForBlockedClients(RedisClient& client, int count) {
    const std::string wanted = absl::StrCat("blocked_clients:", count, "\r\n");
    const absl::Time deadline = absl::Now() + absl::Seconds(10);
    while (absl::Now() < deadline) {
      absl::StatusOr<RedisReply> info = client.Command({"INFO", "clients"});
      if (info.ok() && absl::StrContains(info->str(), wanted)) return true;
      absl::SleepFor(absl::Milliseconds(5));
    }
    return false;
  }

  std::unique_ptr<RedisServerProcess> server_;
};

}  // namespace getme::redis::testing
