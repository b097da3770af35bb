#include "redis/redis_address.h"

#include <gtest/gtest.h>

#include "absl/strings/str_cat.h"

namespace getme::redis {
namespace {

RedisAddress Parsed(absl::string_view url) {
  absl::StatusOr<RedisAddress> address = ParseRedisUrl(url);
  EXPECT_TRUE(address.ok()) << url << ": " << address.status();
  return address.value_or(RedisAddress());
}

void ExpectRefused(absl::string_view url, absl::StatusCode code, absl::string_view message) {
  absl::StatusOr<RedisAddress> address = ParseRedisUrl(url);
  ASSERT_FALSE(address.ok()) << url;
  EXPECT_EQ(address.status().code(), code) << url;
  EXPECT_EQ(address.status().message(), message) << url;
}

TEST(ParseRedisUrl, HostAloneTakesTheDefaults) {
  const RedisAddress address = Parsed("redis://redis");
  EXPECT_EQ(address.host, "redis");
  EXPECT_EQ(address.port, 6379);
  EXPECT_EQ(address.user, "");
  EXPECT_EQ(address.password, "");
  EXPECT_EQ(address.db, 0);
}

TEST(ParseRedisUrl, ReadsPortAndDatabase) {
  const RedisAddress address = Parsed("redis://10.0.0.7:6380/3");
  EXPECT_EQ(address.host, "10.0.0.7");
  EXPECT_EQ(address.port, 6380);
  EXPECT_EQ(address.db, 3);
  EXPECT_EQ(Parsed("redis://h:1/").db, 0);
  EXPECT_EQ(Parsed("REDIS://h").host, "h");  // schemes are case-insensitive (RFC 3986)
}

TEST(ParseRedisUrl, ReadsAPasswordAlone) {
  const RedisAddress address = Parsed("redis://:s3cret@redis:6379/2");
  EXPECT_EQ(address.user, "");
  EXPECT_EQ(address.password, "s3cret");
  EXPECT_EQ(address.host, "redis");
  EXPECT_EQ(address.db, 2);
}

TEST(ParseRedisUrl, ReadsAnAclUserAndPassword) {
  const RedisAddress address = Parsed("redis://getme:s3cret@redis");
  EXPECT_EQ(address.user, "getme");
  EXPECT_EQ(address.password, "s3cret");
}

TEST(ParseRedisUrl, DecodesPercentEncodedPasswords) {
  EXPECT_EQ(Parsed("redis://:a%40b%3Ac%2Fd%25@redis").password, "a@b:c/d%");
  // The last '@' ends the password, so an unencoded '@' in it still works.
  EXPECT_EQ(Parsed("redis://:a@b@redis").password, "a@b");
}

TEST(ParseRedisUrl, ReadsIpv6Literals) {
  const RedisAddress address = Parsed("redis://[::1]:7000/1");
  EXPECT_EQ(address.host, "::1");
  EXPECT_EQ(address.port, 7000);
  EXPECT_EQ(address.db, 1);
  EXPECT_EQ(Parsed("redis://[fe80::2]").port, 6379);
}

TEST(ParseRedisUrl, RefusesOtherSchemes) {
  ExpectRefused("redis-host:6379", absl::StatusCode::kInvalidArgument,
                "redis URL: no scheme, expected redis[s]://[[user]:password@]host[:port][/db]");
  ExpectRefused("http://redis:6379", absl::StatusCode::kInvalidArgument,
                "redis URL: scheme 'http://' is neither redis:// nor rediss://, expected "
                "redis[s]://[[user]:password@]host[:port][/db]");
  ExpectRefused("unix:///run/redis.sock", absl::StatusCode::kInvalidArgument,
                "redis URL: scheme 'unix://' is neither redis:// nor rediss://, expected "
                "redis[s]://[[user]:password@]host[:port][/db]");
}

TEST(ParseRedisUrl, RedissIsTlsWithItsFilesAsParameters) {
  const RedisAddress plain = Parsed("redis://redis:6380");
  EXPECT_FALSE(plain.tls);
  const RedisAddress bare = Parsed("rediss://:pw@redis:6380/1");
  EXPECT_TRUE(bare.tls);
  EXPECT_EQ(bare.password, "pw");
  EXPECT_EQ(bare.db, 1);
  EXPECT_EQ(bare.tls_ca_file, "");  // the system's trusted CAs
  EXPECT_EQ(bare.tls_cert_file, "");

  const RedisAddress files = Parsed(
      "rediss://redis/0?cacert=/etc/ca.pem&cert=/etc/my%20client.pem&key=/etc/c.key"
      "&sni=redis.internal");
  EXPECT_TRUE(files.tls);
  EXPECT_EQ(files.host, "redis");
  EXPECT_EQ(files.db, 0);
  EXPECT_EQ(files.tls_ca_file, "/etc/ca.pem");
  EXPECT_EQ(files.tls_cert_file, "/etc/my client.pem");
  EXPECT_EQ(files.tls_key_file, "/etc/c.key");
  EXPECT_EQ(files.tls_server_name, "redis.internal");
  EXPECT_EQ(bare.tls_server_name, "");  // the host
  // Without a path: the parameters follow the authority.
  EXPECT_EQ(Parsed("REDISS://[::1]:7000?cacert=ca.pem").tls_ca_file, "ca.pem");
}

TEST(ParseRedisUrl, RefusesBadTlsParameters) {
  ExpectRefused("rediss://redis?timeout=1", absl::StatusCode::kInvalidArgument,
                "redis URL: unknown parameter 'timeout' (rediss:// takes cacert, cert, key, sni)");
  ExpectRefused("rediss://redis?cacert", absl::StatusCode::kInvalidArgument,
                "redis URL: parameter 'cacert' needs a file path: cacert=PATH");
  ExpectRefused("rediss://redis?cacert=", absl::StatusCode::kInvalidArgument,
                "redis URL: parameter 'cacert' needs a file path: cacert=PATH");
  ExpectRefused("rediss://redis?cacert=%zz", absl::StatusCode::kInvalidArgument,
                "redis URL: parameter 'cacert' needs a file path: cacert=PATH");
  ExpectRefused("rediss://redis?sni=", absl::StatusCode::kInvalidArgument,
                "redis URL: parameter 'sni' needs a host name: sni=NAME");
  ExpectRefused("rediss://redis?cacert=a&cacert=b", absl::StatusCode::kInvalidArgument,
                "redis URL: parameter 'cacert' is given twice");
  ExpectRefused("rediss://redis?cert=c.pem", absl::StatusCode::kInvalidArgument,
                "redis URL: 'cert' and 'key' go together: a client certificate needs its private "
                "key");
  ExpectRefused("rediss://redis?key=c.key", absl::StatusCode::kInvalidArgument,
                "redis URL: 'cert' and 'key' go together: a client certificate needs its private "
                "key");
}

TEST(ParseRedisUrl, RefusesAMissingHost) {
  const std::string message =
      "redis URL: no host, expected redis[s]://[[user]:password@]host[:port][/db]";
  ExpectRefused("redis://", absl::StatusCode::kInvalidArgument, message);
  ExpectRefused("redis://:6379", absl::StatusCode::kInvalidArgument, message);
  ExpectRefused("redis://:pw@/0", absl::StatusCode::kInvalidArgument, message);
  ExpectRefused("redis://[]:6379", absl::StatusCode::kInvalidArgument, message);
}

TEST(ParseRedisUrl, RefusesBadPorts) {
  for (const char* port : {"", "0", "65536", "-1", "+80", " 80", "80x", "port"}) {
    ExpectRefused(absl::StrCat("redis://redis:", port, "/0"), absl::StatusCode::kInvalidArgument,
                  absl::StrCat("redis URL: port '", port, "' is not a number from 1 to 65535"));
  }
  ExpectRefused("redis://[::1]:x", absl::StatusCode::kInvalidArgument,
                "redis URL: port 'x' is not a number from 1 to 65535");
}

TEST(ParseRedisUrl, RefusesBadDatabases) {
  for (const char* db : {"x", "-1", "+1", "1/2", "99999999999"}) {
    ExpectRefused(absl::StrCat("redis://redis:6379/", db), absl::StatusCode::kInvalidArgument,
                  absl::StrCat("redis URL: database '", db,
                               "' is not a number from 0 (the path is /db, e.g. /2)"));
  }
}

TEST(ParseRedisUrl, RefusesQueriesWithoutTlsAndFragments) {
  ExpectRefused("redis://redis?cacert=ca.pem", absl::StatusCode::kInvalidArgument,
                "redis URL: query parameters are for rediss:// (TLS) only: cacert, cert, key, sni");
  for (const char* url : {"redis://redis/0#x", "rediss://redis/0?cacert=a#x"}) {
    ExpectRefused(url, absl::StatusCode::kInvalidArgument,
                  "redis URL: fragments ('#') are not supported");
  }
}

TEST(ParseRedisUrl, RefusesAUserWithoutPassword) {
  ExpectRefused("redis://getme@redis", absl::StatusCode::kInvalidArgument,
                "redis URL: a user without a password; write redis://:password@host for a "
                "password alone or redis://user:password@host for an ACL user");
  ExpectRefused("redis://getme:@redis", absl::StatusCode::kInvalidArgument,
                "redis URL: the password after ':' is empty");
}

TEST(ParseRedisUrl, RefusesBadPercentEncoding) {
  for (const char* url : {"redis://:a%4@redis", "redis://:a%zz@redis", "redis://u%:pw@redis"}) {
    ExpectRefused(url, absl::StatusCode::kInvalidArgument,
                  "redis URL: bad percent-encoding in the user or password (a '%' must be "
                  "followed by two hex digits; write '%25' for '%' itself)");
  }
}

TEST(ParseRedisUrl, RefusesAnUnclosedIpv6Literal) {
  ExpectRefused("redis://[::1:6379", absl::StatusCode::kInvalidArgument,
                "redis URL: host '[' without its closing ']'");
  ExpectRefused("redis://[::1]x", absl::StatusCode::kInvalidArgument,
                "redis URL: unexpected 'x' after the host");
}

TEST(ParseRedisUrl, ErrorsNeverRepeatThePassword) {
  for (const char* url :
       {"redis://:hunter2@redis:port", "redis://:hunter2@redis/x", "redis://:hunter2@"}) {
    absl::StatusOr<RedisAddress> address = ParseRedisUrl(url);
    ASSERT_FALSE(address.ok());
    EXPECT_EQ(address.status().message().find("hunter2"), absl::string_view::npos)
        << address.status();
  }
}

TEST(RedactedUrl, HidesThePasswordOnly) {
  EXPECT_EQ(RedactedUrl(Parsed("redis://:s3cret@redis:6380/2")), "redis://:***@redis:6380/2");
  EXPECT_EQ(RedactedUrl(Parsed("redis://getme:s3cret@redis")), "redis://getme:***@redis:6379/0");
  EXPECT_EQ(RedactedUrl(Parsed("redis://redis")), "redis://redis:6379/0");
  EXPECT_EQ(RedactedUrl(Parsed("redis://[::1]:7000")), "redis://[::1]:7000/0");
  EXPECT_EQ(RedactedUrl(Parsed("rediss://:s3cret@redis?cacert=/ca.pem")),
            "rediss://:***@redis:6379/0");
}

TEST(RedactedUrl, ParsesBackToTheSameServer) {
  const RedisAddress address = Parsed("redis://getme:pw@[::1]:7000/5");
  const RedisAddress reparsed = Parsed(RedactedUrl(address));
  EXPECT_EQ(reparsed.host, address.host);
  EXPECT_EQ(reparsed.port, address.port);
  EXPECT_EQ(reparsed.user, address.user);
  EXPECT_EQ(reparsed.db, address.db);
  EXPECT_FALSE(reparsed.tls);
  EXPECT_TRUE(Parsed(RedactedUrl(Parsed("rediss://redis"))).tls);
}

}  // namespace
}  // namespace getme::redis
