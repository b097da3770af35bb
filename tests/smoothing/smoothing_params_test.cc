// SmoothingParams: the defaults are the paper's Section 4 values (the parameter paragraph before
// Sec. 4.1, γ from Sec. 4.4) and pass Validate(); each out-of-range field fails with
// InvalidArgument naming that field.

#include "getme/smoothing/smoothing_params.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <functional>
#include <limits>
#include <string>

namespace getme {
namespace {

using ::testing::HasSubstr;

constexpr int kTet = TypeIndex(ElementType::kTetrahedron);
constexpr int kHex = TypeIndex(ElementType::kHexahedron);
constexpr int kPyramid = TypeIndex(ElementType::kPyramid);
constexpr int kPrism = TypeIndex(ElementType::kPrism);
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

TEST(SmoothingParamsDefaults, AreValid) { EXPECT_TRUE(SmoothingParams().Validate().ok()); }

TEST(SmoothingParamsDefaults, SimultaneousSubstepUsesSectionFourValues) {
  const SmoothingParams params;
  // σ_tet ∈ [0.77, 0.84], σ_hex ∈ [2.57, 3.45], σ_pyr = 1.86, σ_pri = 1.59.
  EXPECT_EQ(params.simultaneous_sigma_min[kTet], 0.77);
  EXPECT_EQ(params.simultaneous_sigma_max[kTet], 0.84);
  EXPECT_EQ(params.simultaneous_sigma_min[kHex], 2.57);
  EXPECT_EQ(params.simultaneous_sigma_max[kHex], 3.45);
  EXPECT_EQ(params.simultaneous_sigma_min[kPyramid], 1.86);
  EXPECT_EQ(params.simultaneous_sigma_max[kPyramid], 1.86);
  EXPECT_EQ(params.simultaneous_sigma_min[kPrism], 1.59);
  EXPECT_EQ(params.simultaneous_sigma_max[kPrism], 1.59);
  EXPECT_DOUBLE_EQ(params.simultaneous_rho, 2.0 / 3.0);
  EXPECT_EQ(params.simultaneous_eta, 0.25);
  EXPECT_EQ(params.simultaneous_tolerance, 1e-6);
}

TEST(SmoothingParamsDefaults, SequentialSubstepUsesSectionFourValues) {
  const SmoothingParams params;
  EXPECT_EQ(params.sequential_sigma[kTet], 0.81);
  EXPECT_EQ(params.sequential_sigma[kHex], 2.74);
  EXPECT_EQ(params.sequential_sigma[kPyramid], 1.82);
  EXPECT_EQ(params.sequential_sigma[kPrism], 0.85);
  EXPECT_EQ(params.sequential_rho, 0.01);
  EXPECT_EQ(params.penalty_invalid, 0.01);
  EXPECT_EQ(params.penalty_repeat, 0.0005);
  EXPECT_EQ(params.penalty_success, 0.01);
}

TEST(SmoothingParamsDefaults, MethodWarpageLaplaceAndNodes) {
  const SmoothingParams params;
  EXPECT_EQ(params.method, Method::kGetme);  // GETMe = simultaneous, then sequential
  EXPECT_EQ(params.gamma, 0.25);             // Sec. 4.4
  EXPECT_EQ(params.laplace_tolerance, 1e-6);
  EXPECT_TRUE(params.fix_boundary);             // Sec. 3: boundary nodes stay fixed
  EXPECT_FALSE(params.untangle_free_boundary);  // the boundary stays fixed while untangling too
  EXPECT_GE(params.sequential_cycle, 1);
  EXPECT_EQ(params.threads, 0);
}

struct BadField {
  std::string name;                             // test name
  std::function<void(SmoothingParams&)> spoil;  // makes exactly one field invalid
  std::string field;                            // what the message must name
};

void PrintTo(const BadField& bad, std::ostream* os) { *os << bad.name; }

class SmoothingParamsValidate : public ::testing::TestWithParam<BadField> {};

TEST_P(SmoothingParamsValidate, RejectsTheFieldAndNamesIt) {
  SmoothingParams params;
  GetParam().spoil(params);
  const absl::Status status = params.Validate();
  ASSERT_EQ(status.code(), absl::StatusCode::kInvalidArgument) << status;
  EXPECT_THAT(std::string(status.message()), HasSubstr(GetParam().field));
}

#define BAD(test_name, statement, field_name)                      \
  BadField {                                                       \
#test_name, [](SmoothingParams & p) { statement; }, field_name \
  }

INSTANTIATE_TEST_SUITE_P(
    Fields, SmoothingParamsValidate,
    ::testing::Values(
        BAD(NegativeSigmaMinTet, p.simultaneous_sigma_min[kTet] = -0.1,
            "simultaneous_sigma_min[tetrahedron]"),
        BAD(ZeroSigmaMinPrism, p.simultaneous_sigma_min[kPrism] = 0.0,
            "simultaneous_sigma_min[prism]"),
        BAD(NegativeSigmaMaxPyramid, p.simultaneous_sigma_max[kPyramid] = -1.0,
            "simultaneous_sigma_max[pyramid]"),
        BAD(SigmaMaxBelowSigmaMinHex, p.simultaneous_sigma_max[kHex] = 2.0,
            "simultaneous_sigma_max[hexahedron]"),
        BAD(SigmaMaxBelowSigmaMinTet, p.simultaneous_sigma_min[kTet] = 0.9,
            "simultaneous_sigma_max[tetrahedron]"),
        BAD(NaNSigmaMaxPrism, p.simultaneous_sigma_max[kPrism] = kNaN,
            "simultaneous_sigma_max[prism]"),
        BAD(InfiniteSigmaMaxHex, p.simultaneous_sigma_max[kHex] = kInf,
            "simultaneous_sigma_max[hexahedron]"),
        BAD(NegativeSequentialSigmaPyramid, p.sequential_sigma[kPyramid] = -1.82,
            "sequential_sigma[pyramid]"),
        BAD(NaNSequentialSigmaTet, p.sequential_sigma[kTet] = kNaN,
            "sequential_sigma[tetrahedron]"),
        BAD(ZeroSimultaneousRho, p.simultaneous_rho = 0.0, "simultaneous_rho"),
        BAD(SimultaneousRhoAboveOne, p.simultaneous_rho = 1.0001, "simultaneous_rho"),
        BAD(NaNSimultaneousRho, p.simultaneous_rho = kNaN, "simultaneous_rho"),
        BAD(ZeroSequentialRho, p.sequential_rho = 0.0, "sequential_rho"),
        BAD(SequentialRhoAboveOne, p.sequential_rho = 2.0, "sequential_rho"),
        BAD(NaNSequentialRho, p.sequential_rho = kNaN, "sequential_rho"),
        BAD(NegativeEta, p.simultaneous_eta = -0.25, "simultaneous_eta"),
        BAD(NaNEta, p.simultaneous_eta = kNaN, "simultaneous_eta"),
        BAD(NegativeSimultaneousTolerance, p.simultaneous_tolerance = -1e-6,
            "simultaneous_tolerance"),
        BAD(NaNSimultaneousTolerance, p.simultaneous_tolerance = kNaN, "simultaneous_tolerance"),
        BAD(NegativePenaltyInvalid, p.penalty_invalid = -0.01, "penalty_invalid"),
        BAD(NegativePenaltyRepeat, p.penalty_repeat = -0.0005, "penalty_repeat"),
        BAD(NegativePenaltySuccess, p.penalty_success = -0.01, "penalty_success"),
        BAD(NaNPenaltyRepeat, p.penalty_repeat = kNaN, "penalty_repeat"),
        BAD(InfinitePenaltySuccess, p.penalty_success = kInf, "penalty_success"),
        BAD(NegativeLaplaceTolerance, p.laplace_tolerance = -1.0, "laplace_tolerance"),
        BAD(NegativeImprovementTolerance, p.sequential_improvement_tolerance = -1e-3,
            "sequential_improvement_tolerance"),
        BAD(NegativeSimultaneousIterations, p.simultaneous_max_iterations = -1,
            "simultaneous_max_iterations"),
        BAD(NegativeSequentialIterations, p.sequential_max_iterations = -5,
            "sequential_max_iterations"),
        BAD(NegativeStallIterations, p.sequential_stall_iterations = -1,
            "sequential_stall_iterations"),
        BAD(NegativeLaplaceIterations, p.laplace_max_iterations = -1, "laplace_max_iterations"),
        BAD(NegativeUntangleIterations, p.untangle_max_iterations = -1, "untangle_max_iterations"),
        BAD(FreeBoundaryWithoutUntangling, (p.untangle = false, p.untangle_free_boundary = true),
            "untangle_free_boundary"),
        BAD(ZeroSequentialCycle, p.sequential_cycle = 0, "sequential_cycle"),
        BAD(ZeroSequentialBatch, p.sequential_batch = 0, "sequential_batch"),
        BAD(SequentialBatchAbove65536, p.sequential_batch = 65537, "sequential_batch"),
        BAD(ZeroSequentialBatchElements, p.sequential_batch_elements = 0,
            "sequential_batch_elements"),
        BAD(NegativeSequentialBatchBand, p.sequential_batch_band = -0.01, "sequential_batch_band"),
        BAD(NaNSequentialBatchBand, p.sequential_batch_band = kNaN, "sequential_batch_band"),
        BAD(NegativeSequentialCycle, p.sequential_cycle = -1000, "sequential_cycle"),
        BAD(SimultaneousBacktrackingAbove30, p.simultaneous_backtracking_steps = 31,
            "simultaneous_backtracking_steps"),
        BAD(NegativeSimultaneousBacktracking, p.simultaneous_backtracking_steps = -1,
            "simultaneous_backtracking_steps"),
        BAD(SequentialBacktrackingAbove30, p.sequential_backtracking_steps = 31,
            "sequential_backtracking_steps"),
        BAD(NegativeSequentialBacktracking, p.sequential_backtracking_steps = -1,
            "sequential_backtracking_steps"),
        BAD(ThreadsAbove1024, p.threads = 1025, "threads"),
        BAD(NegativeThreads, p.threads = -1, "threads"),
        BAD(ThreeKernelLanes, p.kernel_lanes = 3, "kernel_lanes"),
        BAD(SixteenKernelLanes, p.kernel_lanes = 16, "kernel_lanes"),
        BAD(NegativeKernelLanes, p.kernel_lanes = -2, "kernel_lanes"),
        BAD(ZeroGamma, p.gamma = 0.0, "gamma"), BAD(NegativeGamma, p.gamma = -0.25, "gamma"),
        BAD(NaNGamma, p.gamma = kNaN, "gamma")),
    [](const ::testing::TestParamInfo<BadField>& info) { return info.param.name; });

#undef BAD

TEST(SmoothingParamsValidate, AcceptsTheEdgesOfEachRange) {
  SmoothingParams params;
  params.simultaneous_sigma_max = params.simultaneous_sigma_min;  // σ_max = σ_min is allowed
  params.simultaneous_rho = 1.0;
  params.sequential_rho = 1.0;
  params.gamma = 1.0;
  params.simultaneous_eta = 0.0;
  params.simultaneous_tolerance = 0.0;
  params.penalty_repeat = 0.0;
  params.penalty_success = 0.0;
  params.simultaneous_max_iterations = 0;
  params.sequential_max_iterations = 0;
  params.sequential_stall_iterations = 0;
  params.sequential_cycle = 1;
  params.simultaneous_backtracking_steps = 30;
  params.sequential_backtracking_steps = 0;
  params.threads = 1024;
  EXPECT_TRUE(params.Validate().ok()) << params.Validate();
  for (int lanes : {0, 2, 4, 8}) {
    params.kernel_lanes = lanes;  // whether this machine runs the width is Smooth()'s to say
    EXPECT_TRUE(params.Validate().ok()) << params.Validate();
  }
}

}  // namespace
}  // namespace getme
