#include "cli/cli_options.h"

#include <gtest/gtest.h>

namespace getme::cli {
namespace {

TEST(CliOptions, LiteralSwitchesOffEverySafeguard) {
  auto options = ParseSmoothArguments({"in.vtk", "out.vtk", "--literal", "--no-untangle"});
  ASSERT_TRUE(options.ok()) << options.status();
  const SmoothingParams params = ToSmoothingParams(*options);
  EXPECT_EQ(params.simultaneous_backtracking_steps, 0);
  EXPECT_EQ(params.sequential_backtracking_steps, 0);
  EXPECT_FALSE(params.sequential_transform_blockers);
  EXPECT_FALSE(params.untangle);
  // Without the flags the safeguards and untangling are on (the defaults).
  auto defaults = ParseSmoothArguments({"in.vtk", "out.vtk"});
  ASSERT_TRUE(defaults.ok());
  const SmoothingParams default_params = ToSmoothingParams(*defaults);
  EXPECT_GT(default_params.simultaneous_backtracking_steps, 0);
  EXPECT_GT(default_params.sequential_backtracking_steps, 0);
  EXPECT_TRUE(default_params.sequential_transform_blockers);
  EXPECT_TRUE(default_params.untangle);
}

}  // namespace
}  // namespace getme::cli
