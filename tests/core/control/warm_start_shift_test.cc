// The warm start: the previous solution shifted by a fraction of a step, the last step held.

#include "core/control/warm_start_shift.h"

#include <gtest/gtest.h>

namespace topay {
namespace {

TEST(WarmStartShiftTest, HalfAStepInterpolatesAndHoldsTheEnd) {
  InputSequence previous = InputSequence::Zero(4, 2);
  previous.u_base.row(0) << 0.0, 0.2, 0.4, 0.6;
  previous.u_base.row(1) << 1.0, 0.0, -1.0, 0.5;
  previous.qd_radps.row(0) << 1.0, 2.0, 3.0, 4.0;
  previous.qd_radps.row(1) << -1.0, -1.0, 1.0, 1.0;
  InputSequence shifted = InputSequence::Zero(4, 2);
  ShiftInputSequence(previous, 0.5, &shifted);
  EXPECT_NEAR(shifted.u_base(0, 0), 0.1, 1e-15);
  EXPECT_NEAR(shifted.u_base(0, 2), 0.5, 1e-15);
  EXPECT_NEAR(shifted.u_base(0, 3), 0.6, 1e-15);  // held past the end
  EXPECT_NEAR(shifted.u_base(1, 1), -0.5, 1e-15);
  EXPECT_NEAR(shifted.qd_radps(0, 1), 2.5, 1e-15);
  EXPECT_NEAR(shifted.qd_radps(1, 1), 0.0, 1e-15);
  EXPECT_NEAR(shifted.qd_radps(0, 3), 4.0, 1e-15);
}

TEST(WarmStartShiftTest, WholeStepsShiftExactly) {
  InputSequence previous = InputSequence::Zero(5, 1);
  previous.u_base.row(0) << 1, 2, 3, 4, 5;
  InputSequence shifted = InputSequence::Zero(5, 1);
  ShiftInputSequence(previous, 2.0, &shifted);
  EXPECT_EQ(shifted.u_base(0, 0), 3.0);
  EXPECT_EQ(shifted.u_base(0, 2), 5.0);
  EXPECT_EQ(shifted.u_base(0, 4), 5.0);
  ShiftInputSequence(previous, 0.0, &shifted);
  EXPECT_EQ(shifted.u_base, previous.u_base);
}

}  // namespace
}  // namespace topay
