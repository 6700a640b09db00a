// topay-track-bench's smoke run: one smooth trajectory file (as topay-bench --dump-trajectories
// writes them) tracked by the NMPC driving the simulated plant; it reports one trajectory and
// errors within the goals. A folder without trajectories exits 1, a usage error 2.

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "tests/common/tool_test.h"

#include "core/trajectory/arc_yaw_trajectory.h"
#include "tools/topay_plan/trajectory_json.h"

namespace topay {
namespace {

// 1.5 m of arc, a 0.6 rad turn and every joint +0.4 rad over 6 s, from rest to rest.
ArcYawTrajectory Smooth(const Eigen::VectorXd& q0) {
  const int n = static_cast<int>(q0.size());
  ArcYawTrajectory trajectory(n, 2, {});
  Eigen::MatrixXd head = Eigen::MatrixXd::Zero(n + 2, 3), tail = Eigen::MatrixXd::Zero(n + 2, 3);
  head.col(0).tail(n) = q0;
  tail(0, 0) = 1.5;
  tail(1, 0) = 0.6;
  tail.col(0).tail(n) = q0.array() + 0.4;
  trajectory.Update(Eigen::Vector2d(1.0, 2.0), head, tail, 0.5 * (head.col(0) + tail.col(0)), Eigen::Vector2d(3.0, 3.0));
  return trajectory;
}

TEST(TrackBench, TracksADumpedTrajectoryWithinTheGoals) {
  const std::filesystem::path dir = std::filesystem::path(TOPAY_BINARY_DIR) / "test_out" / "track_bench";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir / "plans");
  std::filesystem::create_directories(dir / "empty");
  const Eigen::VectorXd q0 = Eigen::VectorXd::Zero(7);
  const ArcYawTrajectory trajectory = Smooth(q0);
  plan::TrajectoryFile file;
  file.metadata.scene_kind = "tables";
  file.metadata.task_source = "command line";
  file.metadata.start.x_m = 1.0;
  file.metadata.start.y_m = 2.0;
  file.metadata.start.q_rad = q0;
  file.metadata.status = "success";
  file.pieces = plan::PiecesOf(trajectory);
  file.samples = plan::SampleTrajectory(trajectory, 0.01);
  plan::WriteTrajectoryJson((dir / "plans" / "task_0000_topay_trajectory.json").string(), file);

  const std::string bin = std::string(TOPAY_BINARY_DIR) + "/bin/topay-track-bench";
  const std::string out = (dir / "out.txt").string();
  ASSERT_EQ(ExitCodeOf("'" + bin + "' --trajectories '" + (dir / "plans").string() + "' > '" + out + "' 2>&1"), 0)
      << ReadText(out);
  const std::string text = ReadText(out);
  EXPECT_NE(text.find("1 trajectories"), std::string::npos) << text;
  const std::size_t at = text.find("base position RMS ");
  ASSERT_NE(at, std::string::npos) << text;
  const double position_rms = std::stod(text.substr(at + 18));
  EXPECT_LT(position_rms, 0.03) << text;
  const std::size_t yaw = text.find("yaw RMS ", at);
  ASSERT_NE(yaw, std::string::npos);
  EXPECT_LT(std::stod(text.substr(yaw + 8)), 0.03) << text;
  const std::size_t joints = text.find("joints RMS ", at);
  ASSERT_NE(joints, std::string::npos);
  EXPECT_LT(std::stod(text.substr(joints + 11)), 0.02) << text;

  EXPECT_EQ(ExitCodeOf("'" + bin + "' --trajectories '" + (dir / "empty").string() + "' > /dev/null 2>&1"), 1);
  EXPECT_EQ(ExitCodeOf("'" + bin + "' > /dev/null 2>&1"), 2);  // usage: --trajectories missing
}

}  // namespace
}  // namespace topay
