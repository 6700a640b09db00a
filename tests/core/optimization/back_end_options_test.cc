#include "core/optimization/back_end_options.h"

#include <limits>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "core/optimization/flatness_optimizer.h"
#include "core/optimization/trajectory_optimizer.h"

namespace topay {
namespace {

std::string CheckMessage(const BackEndOptions& o) {
  try {
    CheckBackEndOptions(o, "Owner");
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(BackEndOptionsTest, DefaultsPassAndBadFieldsAreNamed) {
  EXPECT_EQ(CheckMessage(BackEndOptions()), "");
  BackEndOptions o;
  o.time_limit_s = 0.0;
  EXPECT_NE(CheckMessage(o).find("Owner: time_limit_s"), std::string::npos) << CheckMessage(o);
  o = {};
  o.time_limit_s = std::numeric_limits<double>::quiet_NaN();
  EXPECT_NE(CheckMessage(o).find("time_limit_s"), std::string::npos);
  o = {};
  o.time_limit_s = std::numeric_limits<double>::infinity();  // no limit
  EXPECT_EQ(CheckMessage(o), "");
  o = {};
  o.ee_position_tolerance_m = -0.01;
  EXPECT_NE(CheckMessage(o).find("ee_position_tolerance_m"), std::string::npos);
  o = {};
  o.ee_orientation_tolerance_rad = 0.0;
  EXPECT_NE(CheckMessage(o).find("ee_orientation_tolerance_rad"), std::string::npos);
  o = {};
  o.alm.rho_growth = 0.5;
  EXPECT_NE(CheckMessage(o).find("Owner: alm.rho_growth"), std::string::npos);
  o = {};
  o.lbfgs.memory = 0;
  EXPECT_NE(CheckMessage(o), "");
  o = {};
  o.warm_start.min_pieces = 0;
  EXPECT_NE(CheckMessage(o), "");
}

// Both back ends' options are a BackEndOptions: one set of shared fields, one default.
TEST(BackEndOptionsTest, BothBackEndsShareOneStructWithOneSetOfDefaults) {
  const BackEndOptions shared;
  const TrajectoryOptimizerOptions arc;
  const FlatnessOptimizerOptions flat;
  for (const BackEndOptions* o : {static_cast<const BackEndOptions*>(&arc),
                                  static_cast<const BackEndOptions*>(&flat)}) {
    EXPECT_EQ(o->alm.rho_initial, shared.alm.rho_initial);
    EXPECT_EQ(o->alm.max_outer_iterations, shared.alm.max_outer_iterations);
    EXPECT_EQ(o->ee_position_tolerance_m, shared.ee_position_tolerance_m);
    EXPECT_EQ(o->time_limit_s, shared.time_limit_s);
    EXPECT_EQ(o->lbfgs.memory, shared.lbfgs.memory);
    EXPECT_EQ(o->warm_start.min_pieces, shared.warm_start.min_pieces);
  }
}

}  // namespace
}  // namespace topay
