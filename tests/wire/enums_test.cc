#include "getme_wire/enums.h"

#include <gtest/gtest.h>

namespace getme::wire {
namespace {

TEST(WireEnums, EveryMethodRoundTripsAndUnspecifiedIsGetme) {
  for (Method method : {Method::kGetme, Method::kSimultaneous, Method::kSequential,
                        Method::kWarpage, Method::kSmartLaplace, Method::kLaplace}) {
    const v1::Method wire = ToWireMethod(method);
    EXPECT_NE(wire, v1::METHOD_UNSPECIFIED) << MethodName(method);
    EXPECT_EQ(FromWireMethod(wire), method) << MethodName(method);
  }
  EXPECT_EQ(ToWireMethod(Method::kSmartLaplace), v1::METHOD_SMART_LAPLACE);
  EXPECT_EQ(FromWireMethod(v1::METHOD_UNSPECIFIED), Method::kGetme);
  EXPECT_EQ(FromWireMethod(99), std::nullopt);
}

TEST(WireEnums, EveryPhaseRoundTripsAndUnknownIsNone) {
  for (Phase phase : {Phase::kUntangle, Phase::kSimultaneous, Phase::kSequential, Phase::kWarpage,
                      Phase::kSmartLaplace, Phase::kLaplace, Phase::kPolish, Phase::kLayers}) {
    const v1::Phase wire = ToWirePhase(phase);
    EXPECT_NE(wire, v1::PHASE_UNSPECIFIED) << PhaseName(phase);
    EXPECT_EQ(FromWirePhase(wire), phase) << PhaseName(phase);
  }
  EXPECT_EQ(ToWirePhase(Phase::kUntangle), v1::PHASE_UNTANGLE);
  EXPECT_EQ(ToWirePhase(Phase::kPolish), v1::PHASE_POLISH);
  EXPECT_EQ(FromWirePhase(v1::PHASE_UNSPECIFIED), std::nullopt);
  EXPECT_EQ(FromWirePhase(42), std::nullopt);
}

}  // namespace
}  // namespace getme::wire
