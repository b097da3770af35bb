// rediss:// (TLS) connections, against a redis-server listening on a TLS port only, with
// certificates the openssl CLI makes for the test (tests/server/test_certificates.h).
#include <gtest/gtest.h>

#include <string>

#include "absl/strings/match.h"
#include "absl/strings/str_cat.h"
#include "redis/redis_client.h"
#include "redis/redis_script.h"
#include "redis_server_test.h"
#include "test_certificates.h"

namespace getme::redis::testing {
namespace {

using server::testing::GetTestCertificates;
using server::testing::TestCertificates;

class RedisTlsTest : public RedisServerTest {
 protected:
  RedisServerProcess::Options ServerOptions() const override {
    RedisServerProcess::Options options = TlsServerOptions(require_client_certificate_);
    options.password = password_;
    options.extra_bind_addresses = {"127.0.0.2"};
    return options;
  }

  void SetUp() override {
    ASSERT_FALSE(GetTestCertificates().ca_cert.empty()) << "openssl could not make certificates";
    RedisServerTest::SetUp();
  }

  // The fixture's server with the test's client certificate.
  RedisAddress AddressWithClientCertificate() const {
    RedisAddress address = Address();
    address.tls_cert_file = GetTestCertificates().client_cert;
    address.tls_key_file = GetTestCertificates().client_key;
    return address;
  }

  absl::Status ConnectStatus(const RedisAddress& address) const {
    return RedisClient::Connect(address, absl::Seconds(5)).status();
  }

  std::string password_;
  bool require_client_certificate_ = false;
};

TEST_F(RedisTlsTest, CommandsPipelinesAndScriptsWorkOverTls) {
  std::unique_ptr<RedisClient> client = ConnectClient();
  ASSERT_NE(client, nullptr);
  // 3 MB with every byte value: crosses TLS's 16 KiB records and the 64 KiB write pieces.
  std::string value(3 * 1024 * 1024 + 17, '\0');
  for (size_t i = 0; i < value.size(); ++i) value[i] = static_cast<char>(i * 131 % 256);
  ASSERT_TRUE(client->Command({"SET", "blob", value}).ok());
  absl::StatusOr<RedisReply> back = client->Command({"GET", "blob"});
  ASSERT_TRUE(back.ok()) << back.status();
  EXPECT_TRUE(back->str() == value);

  absl::StatusOr<std::vector<RedisReply>> replies = client->Pipeline(
      {{"RPUSH", "list", "a", "b"}, {"LRANGE", "list", "0", "-1"}, {"STRLEN", "blob"}});
  ASSERT_TRUE(replies.ok()) << replies.status();
  ASSERT_EQ(replies->size(), 3u);
  EXPECT_EQ((*replies)[0].integer(), 2);
  ASSERT_EQ((*replies)[1].elements().size(), 2u);
  EXPECT_EQ((*replies)[1].elements()[1].str(), "b");
  EXPECT_EQ((*replies)[2].integer(), static_cast<int64_t>(value.size()));

  const RedisScript script("return redis.call('INCRBY', KEYS[1], ARGV[1])");
  absl::StatusOr<RedisReply> sum = client->Eval(script, {"counter"}, {"40"});
  ASSERT_TRUE(sum.ok()) << sum.status();
  sum = client->Eval(script, {"counter"}, {"2"});
  ASSERT_TRUE(sum.ok()) << sum.status();
  EXPECT_EQ(sum->integer(), 42);
}

// The DNS-name check, without a resolver (a fresh machine may have no /etc/hosts): the server is
// dialled at 127.0.0.1 and the certificate checked for the name `sni` gives.
TEST_F(RedisTlsTest, TheCertificateIsCheckedForTheServerNameWhenOneIsGiven) {
  RedisAddress address = Address();
  address.tls_server_name = "localhost";  // the certificate's DNS name
  EXPECT_TRUE(ConnectStatus(address).ok()) << ConnectStatus(address);
  address.tls_server_name = "redis.example";
  EXPECT_EQ(ConnectStatus(address),
            absl::UnavailableError(
                absl::StrCat("redis: TLS handshake with rediss://127.0.0.1:", server_->port(),
                             "/0 failed: certificate verify failed (hostname mismatch)")));
}

// redis-server sends its CA along with its certificate (OpenSSL builds the chain from its trust
// store), so a client that does not trust that CA reads "self-signed certificate in chain".
TEST_F(RedisTlsTest, AServerCertificateFromAnotherCaIsRefused) {
  RedisAddress address = Address();
  address.tls_ca_file = GetTestCertificates().other_ca_cert;
  EXPECT_EQ(
      ConnectStatus(address),
      absl::UnavailableError(absl::StrCat(
          "redis: TLS handshake with rediss://127.0.0.1:", server_->port(),
          "/0 failed: certificate verify failed (self-signed certificate in certificate chain)")));
}

TEST_F(RedisTlsTest, TheSystemsCasDoNotTrustAPrivateCa) {
  RedisAddress address = Address();
  address.tls_ca_file.clear();
  EXPECT_EQ(
      ConnectStatus(address),
      absl::UnavailableError(absl::StrCat(
          "redis: TLS handshake with rediss://127.0.0.1:", server_->port(),
          "/0 failed: certificate verify failed (self-signed certificate in certificate chain)")));
}

TEST_F(RedisTlsTest, ACertificateForAnotherAddressIsRefused) {
  RedisAddress address = Address();
  address.host = "127.0.0.2";  // the server listens there too, but its certificate names 127.0.0.1
  EXPECT_EQ(ConnectStatus(address),
            absl::UnavailableError(
                absl::StrCat("redis: TLS handshake with rediss://127.0.0.2:", server_->port(),
                             "/0 failed: certificate verify failed (IP address mismatch)")));
}

TEST_F(RedisTlsTest, PlainAndTlsDoNotMix) {
  RedisAddress plain = Address();
  plain.tls = false;
  const absl::Status plain_status = ConnectStatus(plain);
  EXPECT_EQ(plain_status.code(), absl::StatusCode::kUnavailable) << plain_status;

  // A TLS client at a plain port: Redis reads the client's hello as the start of a command and
  // waits for the rest, so the handshake runs out of the connect timeout, which is UNAVAILABLE
  // like any other failure to connect.
  absl::StatusOr<std::unique_ptr<RedisServerProcess>> plain_server = RedisServerProcess::Start();
  ASSERT_TRUE(plain_server.ok()) << plain_server.status();
  RedisAddress tls_to_plain = Address();
  tls_to_plain.port = (*plain_server)->port();
  const absl::Status tls_status =
      RedisClient::Connect(tls_to_plain, absl::Milliseconds(300)).status();
  EXPECT_EQ(tls_status, absl::UnavailableError(absl::StrCat(
                            "redis: TLS handshake with rediss://127.0.0.1:", tls_to_plain.port,
                            "/0 timed out (Resource temporarily unavailable)")));
}

TEST_F(RedisTlsTest, UnusableFilesAreNamed) {
  RedisAddress address = Address();
  address.tls_ca_file = "/nonexistent/ca.pem";
  absl::Status status = ConnectStatus(address);
  EXPECT_EQ(status.code(), absl::StatusCode::kInvalidArgument) << status;
  EXPECT_TRUE(absl::StartsWith(
      status.message(), absl::StrCat("redis: cannot use the TLS CA file '/nonexistent/ca.pem' "
                                     "for rediss://127.0.0.1:",
                                     server_->port(), "/0: ")))
      << status;

  const TestCertificates& certificates = GetTestCertificates();
  address = AddressWithClientCertificate();
  address.tls_key_file = certificates.server_key;  // a key, but not the certificate's
  EXPECT_EQ(ConnectStatus(address),
            absl::InvalidArgumentError(absl::StrCat(
                "redis: cannot use the TLS key file '", certificates.server_key,
                "' for rediss://127.0.0.1:", server_->port(), "/0: key values mismatch")));
}

TEST_F(RedisTlsTest, ABlockingCommandTimesOutAsDeadlineExceeded) {
  std::unique_ptr<RedisClient> client = ConnectClient(absl::Milliseconds(200));
  ASSERT_NE(client, nullptr);
  const absl::Status status = client->Command({"BLPOP", "nothing", "5"}).status();
  EXPECT_EQ(status.code(), absl::StatusCode::kDeadlineExceeded) << status;
  EXPECT_EQ(client->open_connections(), 0);  // a late reply must not answer the next command
  absl::StatusOr<RedisReply> pong = client->Command({"PING"});
  ASSERT_TRUE(pong.ok()) << pong.status();
  EXPECT_EQ(pong->str(), "PONG");
}

class RedisTlsPasswordTest : public RedisTlsTest {
 protected:
  RedisTlsPasswordTest() { password_ = "s3cret"; }
};

TEST_F(RedisTlsPasswordTest, AuthTravelsInsideTls) {
  std::unique_ptr<RedisClient> client = ConnectClient();
  ASSERT_NE(client, nullptr);
  absl::StatusOr<RedisReply> who = client->Command({"ACL", "WHOAMI"});
  ASSERT_TRUE(who.ok()) << who.status();
  EXPECT_EQ(who->str(), "default");

  RedisAddress address = Address();
  address.password = "guess";
  EXPECT_EQ(ConnectStatus(address),
            absl::UnauthenticatedError(absl::StrCat(
                "redis: AUTH on rediss://:***@127.0.0.1:", server_->port(),
                "/0 refused: WRONGPASS invalid username-password pair or user is disabled.")));
}

class RedisTlsClientCertificateTest : public RedisTlsTest {
 protected:
  RedisTlsClientCertificateTest() { require_client_certificate_ = true; }
};

TEST_F(RedisTlsClientCertificateTest, TheServerRequiresTheClientsCertificate) {
  const absl::Status without = ConnectStatus(Address());
  EXPECT_EQ(without.code(), absl::StatusCode::kUnavailable) << without;
  // TLS 1.3 ends the handshake before the server has checked the client: the first command
  // (PING) reads the server's alert ("tlsv13 alert certificate required") or, when the server
  // has already closed the connection, a reset.
  EXPECT_TRUE(absl::StartsWith(without.message(), absl::StrCat("redis: PING on rediss://127.0.0.1:",
                                                               server_->port(), "/0 failed: ")))
      << without;

  absl::StatusOr<std::unique_ptr<RedisClient>> with =
      RedisClient::Connect(AddressWithClientCertificate(), absl::Seconds(5));
  ASSERT_TRUE(with.ok()) << with.status();
  absl::StatusOr<RedisReply> pong = (*with)->Command({"PING"});
  ASSERT_TRUE(pong.ok()) << pong.status();
  EXPECT_EQ(pong->str(), "PONG");
}

}  // namespace
}  // namespace getme::redis::testing
