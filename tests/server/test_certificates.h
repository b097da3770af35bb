#pragma once

#include <string>

namespace getme::server::testing {

// PEM files made at test time with Debian's openssl CLI (elliptic-curve keys: quick to make),
// valid for a day. Paths of files in a fresh temporary directory.
struct TestCertificates {
  std::string ca_cert;                  // a self-signed CA
  std::string server_cert, server_key;  // signed by the CA, for IP 127.0.0.1 and DNS localhost
  std::string client_cert, client_key;  // signed by the CA, for client authentication
  std::string other_ca_cert;            // a second CA that signed nothing here
};

// Made once per test process; an empty struct (and a test failure) when openssl fails.
const TestCertificates& GetTestCertificates();

std::string ReadTextFile(const std::string& path);
void WriteTextFile(const std::string& path, const std::string& contents);

}  // namespace getme::server::testing
