// ParseMethod and MethodName: every method has a name that parses back to it; an unknown name is
// an InvalidArgument that lists the valid names.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include "getme/smoothing/smoothing_params.h"

namespace getme {
namespace {

using ::testing::AllOf;
using ::testing::HasSubstr;

const std::vector<std::pair<std::string, Method>>& AllMethods() {
  static const std::vector<std::pair<std::string, Method>> kMethods = {
      {"getme", Method::kGetme},
      {"simultaneous", Method::kSimultaneous},
      {"sequential", Method::kSequential},
      {"warpage", Method::kWarpage},
      {"smart-laplace", Method::kSmartLaplace},
      {"laplace", Method::kLaplace}};
  return kMethods;
}

TEST(MethodNames, EveryNameParsesToItsMethod) {
  for (const auto& [name, method] : AllMethods()) {
    const absl::StatusOr<Method> parsed = ParseMethod(name);
    ASSERT_TRUE(parsed.ok()) << name << ": " << parsed.status();
    EXPECT_EQ(*parsed, method) << name;
  }
}

TEST(MethodNames, MethodNameRoundTrips) {
  for (const auto& [name, method] : AllMethods()) {
    EXPECT_EQ(std::string(MethodName(method)), name);
    const absl::StatusOr<Method> parsed = ParseMethod(MethodName(method));
    ASSERT_TRUE(parsed.ok()) << parsed.status();
    EXPECT_EQ(*parsed, method);
  }
}

TEST(MethodNames, UnknownNameListsTheValidNames) {
  for (const std::string bad : {"mesquite", "", "GETME", "smart_laplace", "getme "}) {
    const absl::StatusOr<Method> parsed = ParseMethod(bad);
    ASSERT_EQ(parsed.status().code(), absl::StatusCode::kInvalidArgument) << "'" << bad << "'";
    const std::string message(parsed.status().message());
    EXPECT_THAT(message, HasSubstr("'" + bad + "'"));
    for (const auto& [name, method] : AllMethods()) EXPECT_THAT(message, HasSubstr(name));
  }
}

}  // namespace
}  // namespace getme
