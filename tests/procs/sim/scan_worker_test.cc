// The LiDAR's thread (procs/sim/scan_worker.h): the scans made on it equal the inline ones of
// the same core (same states, worlds and random draws in the same order); with
// latest_scan_only, a thread that is behind skips the waiting scans, never a world update.

#include "procs/sim/scan_worker.h"

#include <gtest/gtest.h>

#include <condition_variable>
#include <mutex>

#include "procs/sim/output_digest.h"
#include "procs/sim/sim_setup.h"

namespace topay::simproc {
namespace {

SimOptions Options() {
  SimOptions o;
  o.robot_urdf = std::string(TOPAY_SOURCE_DIR) + "/config/robot/topay_mm.urdf";
  o.robot_yaml = std::string(TOPAY_SOURCE_DIR) + "/config/robot/topay_mm.yaml";
  o.lidar_file = std::string(TOPAY_SOURCE_DIR) + "/config/sim/lidar.yaml";
  o.scene = "tables";
  o.scene_seed = 4;
  return o;
}

// Drives a curve for 1.5 s and makes box 10 disappear at 0.55 s (between two scans).
void Drive(SimCore* core) {
  sim::SimEvent gone;
  gone.trigger = sim::SimEvent::Trigger::kAtTime;
  gone.at_s = 0.55;
  gone.action = sim::SimEvent::Action::kDisappear;
  gone.box_id = 10;
  core->AddEvent(gone);
  sim::ActuatorCommand c;
  c.v_mps = 0.6;
  c.omega_radps = 0.5;
  c.qdot_radps = Eigen::VectorXd::Constant(7, 0.3);
  for (int k = 0; k < 750; ++k) {
    if (k % 10 == 0) core->Command(c);
    core->Step();
  }
}

struct Deferred : OutputDigest {
  ScanWorker* worker = nullptr;
  void OnScanDue(const WholeBodyState& state, double t_s) override { worker->Request(state, t_s); }
  void OnWorldChanged(const std::vector<OrientedBox>& boxes) override { worker->SetWorld(boxes); }
};

TEST(ScanWorker, ScansOnItsThreadEqualTheInlineScans) {
  SimAssembly inline_sim = AssembleSim(Options());
  OutputDigest inline_digest;
  inline_sim.core->SetListener(&inline_digest);
  Drive(inline_sim.core.get());

  SimAssembly threaded_sim = AssembleSim(Options());
  ScanWorker worker(threaded_sim.core->ReleaseScanSensor());
  Deferred deferred;
  deferred.worker = &worker;
  threaded_sim.core->SetListener(&deferred);
  EXPECT_TRUE(threaded_sim.core->has_lidar());
  Drive(threaded_sim.core.get());
  worker.Drain();
  EXPECT_EQ(worker.backlog(), 0);
  OutputDigest threaded_scans;
  for (const ScanResult& scan : worker.TakeCompleted()) threaded_scans.OnScan(scan);

  EXPECT_EQ(inline_digest.num_scans, 15);
  EXPECT_EQ(threaded_scans.num_scans, 15);
  EXPECT_EQ(threaded_scans.scans(), inline_digest.scans());
  EXPECT_EQ(deferred.states(), inline_digest.states());
  EXPECT_EQ(threaded_sim.core->counts().scans, 15);
  EXPECT_TRUE(worker.TakeCompleted().empty());
}

// A sensor whose scans wait until Release: the worker's thread is then behind on purpose.
class HeldSensor : public ScanSensor {
 public:
  void SetWorld(const std::vector<OrientedBox>& boxes) override {
    std::lock_guard lock(mutex_);
    worlds_.push_back(boxes.size());
  }
  ScanResult Scan(const WholeBodyState&, double t_s) override {
    std::unique_lock lock(mutex_);
    ++started_;
    changed_.notify_all();
    changed_.wait(lock, [this] { return released_; });
    ScanResult r;
    r.t_s = t_s;
    r.rays = static_cast<int>(worlds_.size());  // the world updates applied before this scan
    return r;
  }
  double rate_hz() const override { return 10.0; }
  void WaitUntilScanning() {
    std::unique_lock lock(mutex_);
    changed_.wait(lock, [this] { return started_ > 0; });
  }
  void Release() {
    std::lock_guard lock(mutex_);
    released_ = true;
    changed_.notify_all();
  }

 private:
  std::mutex mutex_;
  std::condition_variable changed_;
  std::vector<std::size_t> worlds_;
  int started_ = 0;
  bool released_ = false;
};

std::vector<double> ScanTimes(ScanWorker* worker) {
  std::vector<double> t_s;
  for (const ScanResult& scan : worker->TakeCompleted()) t_s.push_back(scan.t_s);
  return t_s;
}

WholeBodyState AtRest() {
  WholeBodyState state;
  state.q_rad = Eigen::VectorXd::Zero(7);
  return state;
}

TEST(ScanWorker, LatestScanOnlySkipsTheWaitingScansButNoWorldUpdate) {
  auto sensor = std::make_unique<HeldSensor>();
  HeldSensor* held = sensor.get();
  ScanWorker worker(std::move(sensor), nullptr, /*latest_scan_only=*/true);
  worker.Request(AtRest(), 0.0);
  held->WaitUntilScanning();  // the first scan runs (held): what follows waits
  worker.Request(AtRest(), 0.1);
  worker.SetWorld(std::vector<OrientedBox>(1));
  worker.Request(AtRest(), 0.2);
  worker.SetWorld(std::vector<OrientedBox>(2));
  worker.Request(AtRest(), 0.3);
  EXPECT_EQ(worker.dropped(), 2) << "the scans of 0.1 and 0.2 s were still waiting";
  held->Release();
  worker.Drain();
  EXPECT_EQ(worker.backlog(), 0);
  const std::vector<ScanResult> scans = worker.TakeCompleted();
  ASSERT_EQ(scans.size(), 2u);
  EXPECT_EQ(scans[0].t_s, 0.0);
  EXPECT_EQ(scans[1].t_s, 0.3);
  EXPECT_EQ(scans[1].rays, 2) << "both world updates were applied before the newest scan";
}

TEST(ScanWorker, WithoutLatestScanOnlyEveryScanIsMadeInOrder) {
  auto sensor = std::make_unique<HeldSensor>();
  HeldSensor* held = sensor.get();
  ScanWorker worker(std::move(sensor));
  std::vector<double> requested_s;
  for (int k = 0; k < 4; ++k) {
    requested_s.push_back(0.1 * k);
    worker.Request(AtRest(), requested_s.back());
  }
  held->WaitUntilScanning();
  held->Release();
  worker.Drain();
  EXPECT_EQ(ScanTimes(&worker), requested_s);
  EXPECT_EQ(worker.dropped(), 0);
}

}  // namespace
}  // namespace topay::simproc
