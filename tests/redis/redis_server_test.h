#pragma once

#include <gtest/gtest.h>

#include <memory>
#include <string>

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

  std::unique_ptr<RedisServerProcess> server_;
};

}  // namespace getme::redis::testing
