#pragma once
// The simulator core's view of its two world-reading sensors, the LiDAR and the ground-truth
// collision monitor (sim/lidar/, sim/monitor/), behind small interfaces: the core is tested
// with fakes, and the adapters (lidar_adapter.h, monitor_adapter.h) are the only code that
// knows the libraries' own types.

#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "core/geometry/oriented_box.h"
#include "core/robot/whole_body_state.h"

namespace topay::simproc {

/// One LiDAR scan: points p_SP in the sensor frame S, X_WS at capture time.
struct ScanResult {
  double t_s = 0.0;                                   ///< capture time, sim seconds
  Eigen::Isometry3d X_WS = Eigen::Isometry3d::Identity();
  std::vector<Eigen::Vector3f> p_SP;                  ///< points in S, m
  int self_hits = 0;                                  ///< rays that hit the robot itself
  int rays = 0;                                       ///< rays cast
};

/// One contact that started at a plant step.
struct ContactResult {
  double t_s = 0.0;       ///< sim seconds
  std::string body;       ///< robot body, e.g. "base", "sphere 3"
  int box_index = -1;     ///< index into the boxes last given to SetWorld (-1: self collision)
  double depth_m = 0.0;   ///< penetration depth, m
};

struct ContactCounts {
  std::int64_t events = 0;          ///< contacts started
  std::int64_t steps_in_contact = 0;
  std::int64_t steps = 0;           ///< steps checked
  double max_depth_m = 0.0;
  double first_contact_t_s = -1.0;  ///< -1: none yet
};

class ScanSensor {
 public:
  virtual ~ScanSensor() = default;
  virtual void SetWorld(const std::vector<OrientedBox>& boxes) = 0;
  virtual ScanResult Scan(const WholeBodyState& state, double t_s) = 0;
  /// Scans per second of sim time.
  virtual double rate_hz() const = 0;
};

class ContactSensor {
 public:
  virtual ~ContactSensor() = default;
  virtual void SetWorld(const std::vector<OrientedBox>& boxes) = 0;
  /// The contacts that started at this step.
  virtual std::vector<ContactResult> Check(const WholeBodyState& state, double t_s) = 0;
  /// Number of contacts going on now.
  virtual int active() const = 0;
  virtual ContactCounts counts() const = 0;
  /// The monitor's own summary (printed on exit).
  virtual std::string Report() const = 0;
};

}  // namespace topay::simproc
