// The simulator core (procs/sim/sim_core.h) with fake sensors: output rates, the world the
// sensors see as events change it, contacts reported with the world's stable box ids.

#include "procs/sim/sim_core.h"

#include <gtest/gtest.h>

#include "core/io/robot_loader.h"

namespace topay::simproc {
namespace {

const RobotModel& Robot() {
  static const RobotModel model = LoadRobotModel(std::string(TOPAY_SOURCE_DIR) + "/config/robot/topay_mm.urdf",
                                                 std::string(TOPAY_SOURCE_DIR) + "/config/robot/topay_mm.yaml");
  return model;
}

struct FakeWorldLog {
  std::vector<std::vector<OrientedBox>> worlds;
};

class FakeScanner : public ScanSensor {
 public:
  explicit FakeScanner(FakeWorldLog* log) : log_(log) {}
  void SetWorld(const std::vector<OrientedBox>& boxes) override { log_->worlds.push_back(boxes); }
  ScanResult Scan(const WholeBodyState& state, double t_s) override {
    ScanResult r;
    r.t_s = t_s;
    r.X_WS.translation() = Eigen::Vector3d(state.x_m, state.y_m, 0.5);
    r.p_SP.push_back(Eigen::Vector3f(1, 2, 3));
    return r;
  }
  double rate_hz() const override { return 10.0; }

 private:
  FakeWorldLog* log_;
};

// Reports a contact with the box at present index 1 when the base passes x = 0.2 m.
class FakeMonitor : public ContactSensor {
 public:
  void SetWorld(const std::vector<OrientedBox>& boxes) override { boxes_ = boxes.size(); }
  std::vector<ContactResult> Check(const WholeBodyState& state, double t_s) override {
    ++counts_.steps;
    if (state.x_m > 0.2 && !reported_) {
      reported_ = true;
      ++counts_.events;
      return {ContactResult{t_s, "base", 1, 0.01}};
    }
    return {};
  }
  int active() const override { return reported_ ? 1 : 0; }
  ContactCounts counts() const override { return counts_; }
  std::string Report() const override { return "fake"; }
  std::size_t boxes_ = 0;

 private:
  bool reported_ = false;
  ContactCounts counts_;
};

struct Recorder : SimListener {
  std::vector<double> state_times, scan_times;
  std::vector<std::pair<ContactResult, int>> contacts;
  std::vector<std::pair<std::string, std::string>> events;  // (name, error)
  void OnState(const StateSample& s) override { state_times.push_back(s.t_s); }
  void OnScan(const ScanResult& s) override { scan_times.push_back(s.t_s); }
  void OnContact(const ContactResult& c, int id) override { contacts.emplace_back(c, id); }
  void OnEvent(const sim::SimEvent& e, double, const std::string& error) override { events.emplace_back(e.name, error); }
};

TEST(SimCore, PublishesAtItsRatesAndKeepsTheSensorsWorldCurrent) {
  Scene scene;
  for (int i = 0; i < 3; ++i) {
    OrientedBox b;
    b.center_W_m = Eigen::Vector3d(5.0 + i, 5.0, 0.5);
    scene.boxes.push_back(b);
  }
  sim::SimEvent gone;
  gone.name = "box 0 goes";
  gone.trigger = sim::SimEvent::Trigger::kAtTime;
  gone.at_s = 0.1;
  gone.action = sim::SimEvent::Action::kDisappear;
  gone.box_id = 0;
  FakeWorldLog log;
  auto monitor = std::make_unique<FakeMonitor>();
  FakeMonitor* monitor_ptr = monitor.get();
  SimCore core(Robot(), {}, scene, {gone}, std::make_unique<FakeScanner>(&log), std::move(monitor));
  Recorder recorder;
  core.SetListener(&recorder);
  ASSERT_EQ(log.worlds.size(), 1u);
  EXPECT_EQ(log.worlds[0].size(), 3u);

  sim::ActuatorCommand drive;
  drive.v_mps = 0.5;
  drive.qdot_radps = Eigen::VectorXd::Zero(7);
  for (int k = 0; k < 1000; ++k) {  // 2 s
    if (k % 10 == 0) {
      EXPECT_EQ(core.Command(drive), "");
    }
    core.Step();
  }
  EXPECT_NEAR(core.time_s(), 2.0, 1e-12);
  ASSERT_EQ(recorder.state_times.size(), 200u);  // 100 Hz
  EXPECT_NEAR(recorder.state_times[0], 0.01, 1e-12);
  ASSERT_EQ(recorder.scan_times.size(), 20u);    // 10 Hz
  EXPECT_NEAR(recorder.scan_times[0], 0.1, 1e-12);
  EXPECT_EQ(core.counts().scans, 20);

  // The event removed box 0: the sensors got the new world (boxes 1 and 2).
  ASSERT_EQ(recorder.events.size(), 1u);
  EXPECT_EQ(recorder.events[0], std::make_pair(std::string("box 0 goes"), std::string()));
  ASSERT_EQ(log.worlds.size(), 2u);
  ASSERT_EQ(log.worlds[1].size(), 2u);
  EXPECT_EQ(log.worlds[1][0].center_W_m.x(), 6.0);
  EXPECT_EQ(monitor_ptr->boxes_, 2u);
  // The contact with present index 1 is box id 2.
  ASSERT_EQ(recorder.contacts.size(), 1u);
  EXPECT_EQ(recorder.contacts[0].second, 2);
  EXPECT_EQ(recorder.contacts[0].first.body, "base");

  // A run-time event that cannot apply is reported with its reason.
  sim::SimEvent bad;
  bad.name = "unknown";
  bad.box_id = 99;
  core.AddEvent(bad);
  core.Step();
  ASSERT_EQ(recorder.events.size(), 2u);
  EXPECT_NE(recorder.events[1].second.find("does not exist"), std::string::npos);
  EXPECT_EQ(core.counts().events_failed, 1);
}

}  // namespace
}  // namespace topay::simproc
