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
  EXPECT_FALSE(params.polish);
  EXPECT_EQ(params.sequential_batch, 1);
  // Without the flags the safeguards and untangling are on (the defaults).
  auto defaults = ParseSmoothArguments({"in.vtk", "out.vtk"});
  ASSERT_TRUE(defaults.ok());
  const SmoothingParams default_params = ToSmoothingParams(*defaults);
  EXPECT_GT(default_params.simultaneous_backtracking_steps, 0);
  EXPECT_GT(default_params.sequential_backtracking_steps, 0);
  EXPECT_TRUE(default_params.sequential_transform_blockers);
  EXPECT_TRUE(default_params.untangle);
  EXPECT_TRUE(default_params.polish);
}

TEST(CliOptions, SequentialBatchSetsPicksPerBatchWithinItsRange) {
  auto options = ParseSmoothArguments({"in.vtk", "out.vtk", "--sequential-batch", "16"});
  ASSERT_TRUE(options.ok()) << options.status();
  EXPECT_EQ(ToSmoothingParams(*options).sequential_batch, 16);
  // With --literal too, the explicit batch wins over the literal algorithm's one pick.
  options = ParseSmoothArguments({"in.vtk", "out.vtk", "--literal", "--sequential-batch", "16"});
  ASSERT_TRUE(options.ok()) << options.status();
  EXPECT_EQ(ToSmoothingParams(*options).sequential_batch, 16);
  auto defaults = ParseSmoothArguments({"in.vtk", "out.vtk"});
  ASSERT_TRUE(defaults.ok());
  EXPECT_EQ(ToSmoothingParams(*defaults).sequential_batch, SmoothingParams().sequential_batch);
  for (const char* bad : {"0", "65537", "-3", "many"}) {
    options = ParseSmoothArguments({"in.vtk", "out.vtk", "--sequential-batch", bad});
    ASSERT_FALSE(options.ok()) << bad;
    EXPECT_EQ(options.status().code(), absl::StatusCode::kInvalidArgument);
    EXPECT_NE(options.status().message().find("--sequential-batch"), std::string::npos)
        << options.status();
  }
}

TEST(CliOptions, UntangleBoundaryFreesBoundaryNodesForUntanglingOnly) {
  auto options = ParseSmoothArguments({"in.vtk", "out.vtk", "--untangle-boundary"});
  ASSERT_TRUE(options.ok()) << options.status();
  const SmoothingParams params = ToSmoothingParams(*options);
  EXPECT_TRUE(params.untangle_free_boundary);
  EXPECT_TRUE(params.fix_boundary);  // the smoothing after untangling keeps the boundary
  EXPECT_TRUE(params.Validate().ok());
  auto defaults = ParseSmoothArguments({"in.vtk", "out.vtk"});
  ASSERT_TRUE(defaults.ok());
  EXPECT_FALSE(ToSmoothingParams(*defaults).untangle_free_boundary);
  // Without untangling there is nothing to free the boundary for: the engine names the clash.
  options = ParseSmoothArguments({"in.vtk", "out.vtk", "--untangle-boundary", "--no-untangle"});
  ASSERT_TRUE(options.ok()) << options.status();
  EXPECT_NE(ToSmoothingParams(*options).Validate().message().find("untangle_free_boundary"),
            std::string::npos);
}

TEST(CliOptions, NoPolishAndMaxIterationsReachThePolish) {
  auto options = ParseSmoothArguments({"in.vtk", "out.vtk", "--no-polish"});
  ASSERT_TRUE(options.ok()) << options.status();
  EXPECT_FALSE(ToSmoothingParams(*options).polish);
  EXPECT_TRUE(ToSmoothingParams(*options).sequential_transform_blockers);  // nothing else changes
  options = ParseSmoothArguments({"in.vtk", "out.vtk", "--max-iterations", "3"});
  ASSERT_TRUE(options.ok()) << options.status();
  EXPECT_TRUE(ToSmoothingParams(*options).polish);
  EXPECT_EQ(ToSmoothingParams(*options).polish_max_sweeps, 3);
  EXPECT_EQ(ToSmoothingParams(*options).polish_worst_max_sweeps, 3);
  EXPECT_EQ(ToSmoothingParams(*options).polish_cluster_max_rounds, 3);
}

}  // namespace
}  // namespace getme::cli
