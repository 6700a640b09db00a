#include "core/optimization/augmented_lagrangian.h"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

namespace topay {
namespace {

TEST(AugmentedLagrangianTest, DefaultsAreTheFactsSheetFiguresAndPassTheCheck) {
  const AugmentedLagrangianOptions o;
  EXPECT_EQ(o.rho_initial, 1e4);
  EXPECT_EQ(o.rho_growth, 10.0);
  EXPECT_EQ(o.rho_max, 1e10);
  EXPECT_NO_THROW(CheckAugmentedLagrangianOptions(o, "Test"));
}

TEST(AugmentedLagrangianTest, CheckNamesTheOwnerAndTheField) {
  const auto message = [](AugmentedLagrangianOptions o) {
    try {
      CheckAugmentedLagrangianOptions(o, "Owner");
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  AugmentedLagrangianOptions o;
  o.rho_initial = 0.0;
  EXPECT_EQ(message(o).rfind("Owner: alm.rho_initial", 0), 0u) << message(o);
  o = {};
  o.rho_initial = std::numeric_limits<double>::infinity();
  EXPECT_NE(message(o).find("alm.rho_initial"), std::string::npos);
  o = {};
  o.rho_growth = 0.5;
  EXPECT_NE(message(o).find("alm.rho_growth"), std::string::npos);
  o = {};
  o.rho_max = 10.0;  // below rho_initial
  EXPECT_NE(message(o).find("alm.rho_max"), std::string::npos);
  o = {};
  o.max_outer_iterations = 0;
  EXPECT_NE(message(o).find("alm.max_outer_iterations"), std::string::npos);
  o = {};
  o.orientation_tolerance_rad = 0.0;  // each tolerance is named alone
  EXPECT_NE(message(o).find("alm.orientation_tolerance_rad"), std::string::npos);
  o = {};
  o.position_tolerance_m = -1.0;
  EXPECT_NE(message(o).find("alm.position_tolerance_m"), std::string::npos);
}

TEST(AugmentedLagrangianTest, ConvergedComparesPositionAndRotationSeparately) {
  AugmentedLagrangianOptions o;
  o.position_tolerance_m = 0.01;
  o.orientation_tolerance_rad = 0.1;
  Vector6d r = Vector6d::Zero();
  EXPECT_TRUE(AlmConverged(o, r));
  r << 0.006, 0.008, 0.0, 0.0, 0.0, 0.1;  // |p| = 0.01, |theta| = 0.1: on the bounds
  EXPECT_TRUE(AlmConverged(o, r));
  r(0) = 0.007;
  EXPECT_FALSE(AlmConverged(o, r));
  r << 0.0, 0.0, 0.0, 0.08, 0.07, 0.0;  // |theta| > 0.1
  EXPECT_FALSE(AlmConverged(o, r));
}

// eq. (7): lambda <- lambda + rho r; rho <- min(gamma rho, beta).
TEST(AugmentedLagrangianTest, UpdateIsThePhrStepAndRhoSaturates) {
  AugmentedLagrangianOptions o;
  o.rho_growth = 10.0;
  o.rho_max = 5e4;
  Vector6d lambda;
  lambda << 1.0, -2.0, 0.5, 0.0, 0.25, -1.0;
  Vector6d r;
  r << 0.01, 0.02, -0.03, 0.001, 0.0, 0.5;
  double rho = 1e4;
  const Vector6d expected = lambda + 1e4 * r;
  AlmUpdate(o, r, &lambda, &rho);
  EXPECT_EQ(lambda, expected);
  EXPECT_EQ(rho, 5e4);  // min(1e5, 5e4)
  AlmUpdate(o, r, &lambda, &rho);
  EXPECT_EQ(lambda, expected + 5e4 * r);
  EXPECT_EQ(rho, 5e4);
}

}  // namespace
}  // namespace topay
