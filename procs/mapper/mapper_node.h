#pragma once
// topay-mapper on the bus: POINT_CLOUD and ROBOT_STATE in, MAP_UPDATE out. Each scan is
// checked, filtered with the robot's state at its capture time, inserted into the dense map,
// and the changed voxels go out at once as a delta (a full snapshot every snapshot period and
// first); with no scans an empty delta still goes out every max_silence_s. One scan in N also
// goes to the OctoMap beside the map (OctomapWorker). The heartbeat carries the map's counts
// and the last scan's times: WARN while scans are rejected, come without a robot state or stop.

#include <chrono>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "procs/msgs/cloud_input.h"
#include "procs/mapper/map_journal.h"
#include "procs/mapper/mapper_options.h"
#include "procs/mapper/mapper_stats.h"
#include "procs/mapper/octomap_worker.h"
#include "core/robot/robot_state_history.h"
#include "procs/mapper/scan_mapper.h"
#include "procs/msgs/map_publish_schedule.h"
#include "procs/msgs/robot_state_intake.h"
#include "procs/runtime/process_loop.h"
#include "topay/point_cloud_t.hpp"
#include "topay/robot_state_t.hpp"

namespace topay::mapper {

class MapperNode {
 public:
  /// Subscribes and adds the timers to *loop (before loop->Run()). The loop, the mapper, the
  /// OctoMap worker and the map journal (null: none) outlive the node; every update published
  /// goes into the journal.
  MapperNode(procs::ProcessLoop* loop, ScanMapper* mapper, OctomapWorker* octomap,
             const MapperOptions& options, MapJournal* journal = nullptr);

  void OnCloud(const point_cloud_t& msg);
  void OnRobotState(const robot_state_t& msg);
  /// Publishes the map now: a snapshot when due (or `force_snapshot`), else a delta of the
  /// changes since the last update (possibly empty).
  void Publish(std::int64_t utime, bool force_snapshot = false);

  const MapperStats& stats() const { return stats_; }

 private:
  void OnHealthTimer();
  void Journal(const map_update_t& msg, double now_s);
  double NowS() const;

  procs::ProcessLoop* loop_;
  ScanMapper* mapper_;
  OctomapWorker* octomap_;
  MapJournal* journal_;
  double last_journal_error_s_ = -1e9;
  std::string last_journal_error_;
  MapperOptions options_;
  msgs::RobotStateIntake state_intake_{0};  // decode, continuity gate (the history checks joints)
  RobotStateHistory history_;
  msgs::MapPublishSchedule schedule_;
  msgs::CheckedCloud cloud_;
  std::vector<VoxelChange> pending_;
  std::int64_t last_data_utime_ = 0;
  std::int64_t scans_ = 0;
  std::int64_t rejected_at_last_health_ = 0, without_state_at_last_health_ = 0;
  std::int64_t clouds_at_last_health_ = 0;
  double last_rejection_s_ = -1e9, last_without_state_s_ = -1e9, last_cloud_s_ = 0.0;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
  double last_publish_s_ = -1e9;
  MapperStats stats_;
};

}  // namespace topay::mapper
