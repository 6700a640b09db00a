#include "core/validate/validation_report.h"

#include <set>
#include <string>

#include <gtest/gtest.h>

namespace topay {
namespace {

TEST(ValidationReportTest, EveryCheckAndLimitHasItsOwnName) {
  std::set<std::string> names;
  for (int c = 0; c <= static_cast<int>(ValidationCheck::kStopped); ++c) {
    const std::string name(ToString(static_cast<ValidationCheck>(c)));
    EXPECT_NE(name, "unknown");
    EXPECT_TRUE(names.insert(name).second) << name;
  }
  names.clear();
  for (int l = 0; l <= static_cast<int>(Limit::kJointAcceleration); ++l) {
    const std::string name(ToString(static_cast<Limit>(l)));
    EXPECT_NE(name, "unknown");
    EXPECT_TRUE(names.insert(name).second) << name;
  }
}

TEST(ValidationReportTest, ReportShowsVerdictFailureAndFigures) {
  ValidationReport report;
  report.ok = false;
  report.num_samples = 801;
  report.num_failed_samples = 12;
  report.duration_s = 8.0;
  report.first_failure.check = ValidationCheck::kArmCollision;
  report.first_failure.message = "t = 3.720 s: sphere 5 (link4) vs box 0: clearance -0.002 m";
  report.min_obstacle = {-0.05, 5, 0, 4.0, "sphere 5 (link4) vs box 0"};
  report.min_self = {0.074, 9, -1, 0.0, "self-collision pair 9"};
  report.worst_limit.ratio = 0.46875;
  report.worst_limit.limit = Limit::kCoupledVelocity;
  report.worst_limit.t_s = 4.0;
  report.end_position_error_m = 0.003;
  report.end_orientation_error_rad = 0.001;
  const std::string text = report.Report();
  for (const char* expected :
       {"FAIL", "801 samples", "12 failing", "[arm collision]", "t = 3.720 s: sphere 5 (link4)",
        "min obstacle clearance: -0.05 m, sphere 5 (link4) vs box 0 at 4.000 s",
        "min self clearance: 0.074 m", "min chassis margin: none within reach",
        "worst limit ratio: 0.4688 (coupled v-omega", "end-effector error: 0.003 m, 0.001 rad"}) {
    EXPECT_NE(text.find(expected), std::string::npos) << "missing '" << expected << "' in\n"
                                                      << text;
  }
  report.ok = true;
  report.first_failure = {};
  const std::string passed = report.Report();
  EXPECT_NE(passed.find("PASS"), std::string::npos);
  EXPECT_EQ(passed.find("first failure"), std::string::npos);
}

}  // namespace
}  // namespace topay
