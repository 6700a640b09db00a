// The LiDAR's thread (procs/sim/scan_worker.h): the scans made on it equal the inline ones of
// the same core (same states, worlds and random draws in the same order).

#include "procs/sim/scan_worker.h"

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace topay::simproc
