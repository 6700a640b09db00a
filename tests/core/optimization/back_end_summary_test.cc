#include "core/optimization/back_end_summary.h"

#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

namespace topay {
namespace {

TEST(BackEndSummaryTest, StatusNames) {
  EXPECT_EQ(ToString(BackEndStatus::kSuccess), "success");
  EXPECT_EQ(ToString(BackEndStatus::kNotConverged), "not converged");
  EXPECT_EQ(ToString(BackEndStatus::kCancelled), "cancelled");
  EXPECT_EQ(ToString(BackEndStatus::kInvalidInput), "invalid input");
}

TEST(BackEndSummaryTest, NoTrajectoryIsAnErrorForEitherParameterisation) {
  BackEndSummary summary;
  summary.reason = "path: empty";
  EXPECT_FALSE(summary.success());
  EXPECT_THROW(summary.MakeTrajectory(), std::invalid_argument);
  EXPECT_THROW(summary.Sampled(), std::invalid_argument);
  summary.parameterisation = TrajectoryParameterisation::kFlatness;
  EXPECT_THROW(summary.Sampled(), std::invalid_argument);
}

// A flatness summary is only ever sampled, never rebuilt as an arc length-yaw trajectory.
TEST(BackEndSummaryTest, FlatnessSummaryRefusesMakeTrajectory) {
  BackEndSummary summary;
  summary.parameterisation = TrajectoryParameterisation::kFlatness;
  summary.num_pieces = 2;
  EXPECT_THROW(summary.MakeTrajectory(), std::invalid_argument);
}

TEST(BackEndSummaryTest, ReportNamesTheBackEndTheStatusAndTheReason) {
  BackEndSummary summary;
  summary.status = BackEndStatus::kNotConverged;
  summary.reason = "end-effector error 0.03 m";
  std::string report = summary.Report();
  EXPECT_NE(report.find("arc length-yaw"), std::string::npos) << report;
  EXPECT_NE(report.find("not converged (end-effector error 0.03 m)"), std::string::npos);
  summary.parameterisation = TrajectoryParameterisation::kFlatness;
  summary.num_pieces = 3;
  summary.final_min_speed_cost = 0.25;
  summary.check_violations[static_cast<int>(PenaltyTerm::kAcceleration)] = 0.5;
  report = summary.Report();
  EXPECT_NE(report.find("flatness"), std::string::npos) << report;
  EXPECT_NE(report.find("min speed 0.25"), std::string::npos) << report;
  EXPECT_NE(report.find("dense check violations: " +
                        std::string(ToString(PenaltyTerm::kAcceleration)) + " 0.5"),
            std::string::npos)
      << report;
}

}  // namespace
}  // namespace topay
