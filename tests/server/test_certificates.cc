#include "test_certificates.h"

#include <cstdlib>
#include <fstream>
#include <sstream>

#include "absl/strings/str_cat.h"
#include "gtest/gtest.h"
#include "temp_files.h"

namespace getme::server::testing {
namespace {

constexpr char kNewKey[] = "-newkey ec -pkeyopt ec_paramgen_curve:prime256v1 -nodes";

// Runs an openssl command line in `dir`, its output into dir/openssl.log.
bool OpenSsl(const std::string& dir, const std::string& arguments) {
  const std::string command =
      absl::StrCat("cd '", dir, "' && openssl ", arguments, " >>openssl.log 2>&1");
  if (std::system(command.c_str()) == 0) return true;
  ADD_FAILURE() << "failed: " << command << "\n" << ReadTextFile(dir + "/openssl.log");
  return false;
}

// A CA and certificates it signs for the server (subjectAltName: what clients check against the
// address they dialled) and for a client.
TestCertificates MakeCertificates() {
  std::string pattern = ::testing::TempDir() + "/getme-certs-XXXXXX";
  if (mkdtemp(pattern.data()) == nullptr) {
    ADD_FAILURE() << "mkdtemp " << pattern;
    return {};
  }
  const std::string dir = getme::testing::DeleteWhenTheRunPasses(pattern);
  WriteTextFile(dir + "/server.ext",
                "basicConstraints=CA:FALSE\n"
                "keyUsage=digitalSignature,keyEncipherment\n"
                "extendedKeyUsage=serverAuth\n"
                "subjectAltName=IP:127.0.0.1,DNS:localhost\n");
  WriteTextFile(dir + "/client.ext",
                "basicConstraints=CA:FALSE\n"
                "keyUsage=digitalSignature\n"
                "extendedKeyUsage=clientAuth\n");
  const std::string ca = absl::StrCat("req -x509 ", kNewKey, " -days 1");
  const std::string sign = "x509 -req -days 1 -CA ca.pem -CAkey ca.key -CAcreateserial";
  const bool ok =
      OpenSsl(dir, absl::StrCat(ca, " -keyout ca.key -out ca.pem -subj /CN=getme-test-ca")) &&
      OpenSsl(dir, absl::StrCat(ca,
                                " -keyout other-ca.key -out other-ca.pem "
                                "-subj /CN=getme-other-ca")) &&
      OpenSsl(dir, absl::StrCat("req ", kNewKey,
                                " -keyout server.key -out server.csr -subj /CN=localhost")) &&
      OpenSsl(dir, absl::StrCat(sign, " -in server.csr -out server.pem -extfile server.ext")) &&
      OpenSsl(dir,
              absl::StrCat("req ", kNewKey,
                           " -keyout client.key -out client.csr -subj /CN=getme-test-client")) &&
      OpenSsl(dir, absl::StrCat(sign, " -in client.csr -out client.pem -extfile client.ext"));
  if (!ok) return {};
  return {dir + "/ca.pem",     dir + "/server.pem", dir + "/server.key",
          dir + "/client.pem", dir + "/client.key", dir + "/other-ca.pem"};
}

}  // namespace

const TestCertificates& GetTestCertificates() {
  static const TestCertificates certificates = MakeCertificates();
  return certificates;
}

std::string ReadTextFile(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  std::ostringstream contents;
  contents << file.rdbuf();
  return contents.str();
}

void WriteTextFile(const std::string& path, const std::string& contents) {
  std::ofstream file(path, std::ios::binary | std::ios::trunc);
  file << contents;
  ASSERT_TRUE(file.good()) << "cannot write " << path;
}

}  // namespace getme::server::testing
