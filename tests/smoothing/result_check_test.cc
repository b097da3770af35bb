// ResultCheck (core/getme/smoothing/result_check.h) on hand-broken results: each broken promise is
// caught and named, and an intact result passes.
#include "getme/smoothing/result_check.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "absl/strings/str_cat.h"
#include "getme/meshgen/distorted_hex_block.h"
#include "getme/parallel/thread_pool.h"

namespace getme {
namespace {

using ::testing::HasSubstr;

class ResultCheckTest : public ::testing::Test {
 protected:
  void SetUp() override {
    auto built = meshgen::DistortedHexBlock(3, 3, 3, 0.2, 7);
    ASSERT_TRUE(built.ok()) << built.status();
    mesh_ = std::move(*built);
    // Node 0 is a box corner; the interior node stays movable.
    movable_.assign(mesh_.node_count(), 1);
    movable_[0] = 0;
    interior_ = InteriorNode();
  }

  NodeId InteriorNode() const {
    for (NodeId n = 0; n < mesh_.node_count(); ++n) {
      if (!mesh_.is_boundary(n)) return n;
    }
    return -1;
  }

  absl::Status CheckNow(const ResultCheck& check) {
    return check.Check(mesh_, EvaluateMeshQuality(mesh_, pool_));
  }

  Mesh mesh_;
  std::vector<std::uint8_t> movable_;
  NodeId interior_ = -1;
  ThreadPool pool_{1};
};

TEST_F(ResultCheckTest, AnUntouchedValidMeshPasses) {
  const ResultCheck check(mesh_, movable_);
  EXPECT_TRUE(CheckNow(check).ok());
}

TEST_F(ResultCheckTest, MovedFreeNodesPass) {
  const ResultCheck check(mesh_, movable_);
  mesh_.x()[interior_] += 1e-3;
  EXPECT_TRUE(CheckNow(check).ok());
}

TEST_F(ResultCheckTest, AMovedFixedNodeIsAnInternalErrorNamingIt) {
  const ResultCheck check(mesh_, movable_);
  mesh_.y()[0] = std::nextafter(mesh_.y()[0], 1.0);
  const absl::Status status = CheckNow(check);
  EXPECT_EQ(status.code(), absl::StatusCode::kInternal);
  EXPECT_THAT(status.message(), HasSubstr("fixed node 0 moved"));
}

TEST_F(ResultCheckTest, ASignFlipOfAZeroFixedCoordinateCounts) {
  ASSERT_EQ(mesh_.x()[0], 0.0);  // the box corner at the origin
  const ResultCheck check(mesh_, movable_);
  mesh_.x()[0] = -0.0;
  EXPECT_EQ(CheckNow(check).code(), absl::StatusCode::kInternal);
}

TEST_F(ResultCheckTest, ANonFiniteCoordinateIsAnInternalErrorNamingTheNode) {
  const ResultCheck check(mesh_, movable_);
  mesh_.z()[interior_] = std::numeric_limits<double>::quiet_NaN();
  const absl::Status status = CheckNow(check);
  EXPECT_EQ(status.code(), absl::StatusCode::kInternal);
  EXPECT_THAT(status.message(), HasSubstr(absl::StrCat("node ", interior_, " has a non-finite")));
}

TEST_F(ResultCheckTest, AnInvertedElementIsAnInternalErrorNamingIt) {
  const ResultCheck check(mesh_, movable_);
  // Through the whole block and out the other side: every element at the node inverts.
  mesh_.x()[interior_] += 10.0;
  const MeshQuality after = EvaluateMeshQuality(mesh_, pool_);
  ASSERT_GT(after.invalid, 0);
  const absl::Status status = check.Check(mesh_, after);
  EXPECT_EQ(status.code(), absl::StatusCode::kInternal);
  EXPECT_THAT(status.message(),
              HasSubstr(absl::StrCat(after.invalid, " invalid element(s) in the result, first: ",
                                     after.first_invalid.front())));
}

TEST_F(ResultCheckTest, ANonFiniteReportedQualityIsAnInternalError) {
  const ResultCheck check(mesh_, movable_);
  MeshQuality after = EvaluateMeshQuality(mesh_, pool_);
  after.q_mean = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(check.Check(mesh_, after).code(), absl::StatusCode::kInternal);
  after.q_mean = 0.5;
  after.q_min = 1.5;
  EXPECT_EQ(check.Check(mesh_, after).code(), absl::StatusCode::kInternal);
}

}  // namespace
}  // namespace getme
