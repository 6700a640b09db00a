// topay-planner in deterministic mode (docs/planner.md#replay) as a real process over real LCM in
// a private network namespace (skipped, with the reason, where none can be made). The test
// plays a fixed message sequence stamped on its own clock, far from the wall clock (the
// mapper's snapshot of a small room, the robot at rest every 20 ms, a goal, 3 s later a second
// goal while the first trajectory runs: a moving start), into a fresh planner twice, at the
// messages' pace and as fast as they can be sent. Both runs publish the same TRAJECTORY
// messages byte for byte, timed by the messages: the first starts a replanning budget after
// its goal's utime, the second at its goal's utime + the budget on the first.

#include <gtest/gtest.h>

#include <thread>

#include "graph_test_support.h"
#include "core/io/robot_loader.h"
#include "core/robot/kinematics.h"
#include "procs/msgs/convert_goal.h"
#include "procs/msgs/convert_robot_state.h"
#include "procs/msgs/map_codec.h"
#include "tests/common/arm_state.h"
#include "tests/procs/planner/planner_replay_support.h"
#include "tests/procs/planner/planner_test_support.h"
#include "topay/poly_trajectory_t.hpp"

namespace topay::test {
namespace {

constexpr const char* kLcmUrl = "udpm://239.255.76.67:7667?ttl=0&recv_buf_size=8388608";
/// The messages' clock: 2001-09-09, far from any wall clock the test runs at.
constexpr std::int64_t kT0 = 1'000'000'000'000'000;
constexpr std::int64_t kSecond = 1'000'000;
constexpr double kReplanBudget_s = 1.0;

/// One message of the sequence: its time and how to publish it.
struct Timed {
  std::int64_t utime = 0;
  std::function<void(lcm::LCM*)> publish;
};

/// The encoded bytes of a message (to compare two runs exactly).
std::vector<std::uint8_t> Bytes(const poly_trajectory_t& msg) {
  std::vector<std::uint8_t> bytes(static_cast<std::size_t>(msg.getEncodedSize()));
  msg.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  return bytes;
}

class PlannerDeterministic : public testing::Test {
 protected:
  void SetUp() override {
    std::string why;
    if (!EnterTestNamespace(&why)) GTEST_SKIP() << why;
    dir_ = TestDir("deterministic");
    // No drift trigger or drift check: the test's robot stays at its start while the
    // trajectories run; no stale-map stop: one snapshot plays the mapper.
    WriteText(dir_ + "/planner.yaml", "planner_config: " + std::string(TOPAY_SOURCE_DIR) +
                                          "/config/planner/topay.yaml\ndeterministic: {enabled: true}\nmap: {stale_stop_s: 0}\n"
                                          "triggers: {drift_position_m: 100, drift_yaw_rad: 100, drift_joint_rad: 100, "
                                          "drift_check_position_m: 100, drift_check_yaw_rad: 100, "
                                          "drift_check_joint_rad: 100}\n");
    watcher_ = std::make_unique<HeartbeatWatcher>(kLcmUrl);
    watcher_->lcm().subscribe(std::string(channels::TRAJECTORY), &PlannerDeterministic::OnTrajectory, this);
    sequence_ = Sequence();
  }

  void OnTrajectory(const lcm::ReceiveBuffer*, const std::string&, const poly_trajectory_t* m) {
    trajectories_.push_back(*m);
  }

  goal_t Goal(std::int64_t id, std::int64_t utime, const WholeBodyState& hint) const {
    msgs::PlanGoal goal;
    goal.utime = utime;
    goal.goal_id = id;
    goal.hint = hint;
    goal.X_WE = kinematics_.EndEffectorPose(hint);
    return msgs::ToMessage(goal);
  }

  // The map at kT0, the robot at rest every 20 ms for 6 s, goal 1 at +0.1 s, goal 2 at +3 s.
  std::vector<Timed> Sequence() const {
    std::vector<Timed> out;
    const GridGeometry3 g = planner::testing::RoomGeometry();
    const map_update_t map = msgs::EncodeFullMap(g, planner::testing::StatesOf(g, planner::testing::RoomBoxes()), kT0, 1);
    out.push_back({kT0, [map](lcm::LCM* lcm) { lcm->publish(std::string(channels::MAP_UPDATE), &map); }});
    for (std::int64_t t = kT0 + 20'000; t <= kT0 + 6 * kSecond; t += 20'000) {
      msgs::RobotStateEstimate robot;
      robot.utime = t;
      robot.state = BentArmState(-2.5, -2.5, 0.0);
      robot.qdot_radps = Eigen::VectorXd::Zero(7);
      const robot_state_t msg = msgs::ToMessage(robot);
      out.push_back({t, [msg](lcm::LCM* lcm) { lcm->publish(std::string(channels::ROBOT_STATE), &msg); }});
      if (t == kT0 + 100'000 || t == kT0 + 3 * kSecond) {
        const goal_t goal = t == kT0 + 100'000 ? Goal(1, t, BentArmState(2.3, 2.0, 1.0))
                                               : Goal(2, t, BentArmState(-2.0, 2.5, 0.5));
        out.push_back({t, [goal](lcm::LCM* lcm) { lcm->publish(std::string(channels::GOAL), &goal); }});
      }
    }
    return out;
  }

  // A fresh planner fed the sequence at the messages' pace (or as fast as they go: !paced);
  // its TRAJECTORY messages once it has handled them all.
  std::vector<poly_trajectory_t> Run(const std::string& name, bool paced) {
    trajectories_.clear();
    const pid_t pid = Spawn({BinDir() + "/topay-planner", "--config", dir_ + "/planner.yaml", "--name", name,
                             "--lcm-url", kLcmUrl}, dir_ + "/" + name + ".txt");
    EXPECT_TRUE(watcher_->SpinUntil([&] { return watcher_->last.contains(name); }, 10.0));
    const Clock::time_point start = Clock::now();
    for (const Timed& m : sequence_) {
      const auto due = start + std::chrono::microseconds(m.utime - kT0);
      while (paced && Clock::now() < due) watcher_->lcm().handleTimeout(1);
      m.publish(&watcher_->lcm());
    }
    EXPECT_TRUE(WaitUntilInboxEmpty(watcher_.get(), name, 120.0, static_cast<std::int64_t>(sequence_.size())))
        << ReadText(dir_ + "/" + name + ".txt");
    kill(pid, SIGINT);
    EXPECT_EQ(WaitFor(pid, 10.0), 0) << ReadText(dir_ + "/" + name + ".txt");
    watcher_->Spin(0.2);
    EXPECT_EQ(MessagesHandled(ReadText(dir_ + "/" + name + ".txt")), static_cast<std::int64_t>(sequence_.size()));
    return trajectories_;
  }

  RobotModel model_ = LoadRobotModel(TOPAY_SOURCE_DIR "/config/robot/topay_mm.urdf",
                                     TOPAY_SOURCE_DIR "/config/robot/topay_mm.yaml");
  Kinematics kinematics_{model_};
  std::string dir_;
  std::unique_ptr<HeartbeatWatcher> watcher_;
  std::vector<Timed> sequence_;
  std::vector<poly_trajectory_t> trajectories_;
};

TEST_F(PlannerDeterministic, TheSameMessagesAtAnyPaceGiveTheSameTrajectoriesTimedByTheMessages) {
  const std::vector<poly_trajectory_t> paced = Run("paced", true);
  ASSERT_EQ(paced.size(), 2u) << ReadText(dir_ + "/paced.txt");
  // Message time: the goal's utime (the newest message) + the budget, whatever the wall clock.
  EXPECT_EQ(paced[0].goal_id, 1);
  EXPECT_EQ(paced[0].utime, kT0 + 100'000);
  EXPECT_EQ(paced[0].start_utime, kT0 + 100'000 + static_cast<std::int64_t>(kReplanBudget_s * kSecond));
  EXPECT_EQ(paced[1].goal_id, 2);
  EXPECT_EQ(paced[1].start_utime, kT0 + 3 * kSecond + static_cast<std::int64_t>(kReplanBudget_s * kSecond))
      << "a moving start on trajectory 1, a budget after goal 2";

  const std::vector<poly_trajectory_t> fast = Run("fast", false);
  ASSERT_EQ(fast.size(), paced.size()) << ReadText(dir_ + "/fast.txt");
  for (std::size_t k = 0; k < paced.size(); ++k) {
    EXPECT_TRUE(Bytes(fast[k]) == Bytes(paced[k])) << "trajectory " << paced[k].trajectory_id << " differs";
  }
}

}  // namespace
}  // namespace topay::test
