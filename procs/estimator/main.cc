// topay-estimator: the robot state estimator of the graph (docs/estimator.md). BASE_POSE
// (localisation), BASE_VELOCITY (wheel odometry), JOINT_STATE and GRIPPER_STATE in; ROBOT_STATE
// out at 100 Hz while the estimate is valid (an EKF on SE(2), core/estimation). Exit codes: 0,
// 1 config or file error, 2 usage error.

#include <CLI/CLI.hpp>
#include <spdlog/spdlog.h>

#include <cstdio>
#include <memory>
#include <optional>

#include "procs/estimator/estimator_config.h"
#include "procs/estimator/estimator_node.h"
#include "procs/runtime/process_loop.h"

using namespace topay;
using namespace topay::estimator;

int main(int argc, char** argv) {
  CLI::App app{"topay-estimator: ROBOT_STATE at 100 Hz from localisation, wheel odometry and joint states"};
  procs::ProcessOptions process;
  procs::AddCommonFlags(&app, "topay-estimator", &process);
  if (const std::optional<int> code = procs::ParseFlags(&app, argc, argv)) return *code;

  EstimatorProcessOptions options;
  std::unique_ptr<EstimatorNode> node;
  try {
    if (!process.config_path.empty()) options = LoadEstimatorProcessOptions(process.config_path);
    node = std::make_unique<EstimatorNode>(options);
  } catch (const std::exception& e) {  // ConfigError, bad options
    spdlog::error("{}", e.what());
    return procs::kExitConfigError;
  }
  procs::ProcessLoop loop(process);
  if (!loop.ok()) {
    spdlog::error("{}", loop.error());
    return procs::kExitConfigError;
  }
  ConnectEstimatorNode(&loop, node.get(), 1.0 / options.publish_rate_hz);
  spdlog::info("{}: {:.0f} Hz; timeouts: odometry {:.3f} s, joints {:.3f} s, pose {:.3f} s, gripper {:.3f} s; "
               "gate chi2 {:.2f}, re-initialise after {} rejections, history {} events / {:.3f} s",
               process.name, options.publish_rate_hz, options.odometry_timeout_s, options.joints_timeout_s,
               options.pose_timeout_s, options.gripper_timeout_s, options.filter.gate_chi2,
               options.filter.reinit_after_rejections, options.filter.history_capacity, options.filter.max_delay_s);
  const int code = loop.Run();
  std::printf("%s", node->Report().c_str());
  std::fflush(stdout);
  return code;
}
