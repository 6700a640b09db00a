#pragma once
// The OctoMap beside the dense map, on a thread of its own at low priority: OctoMap's
// insertion of a scan takes ~10 scan periods at 0.05 m (docs/benchmarks.md), so it gets one
// scan in N and never holds up the dense map's critical path.

#include <condition_variable>
#include <mutex>
#include <span>
#include <string>
#include <thread>
#include <vector>

#include <Eigen/Core>

#include "procs/mapper/octomap_mirror.h"

namespace topay::mapper {

/// Counts and times of the worker (a copy, consistent).
struct OctomapWorkerStats {
  std::int64_t submitted = 0;  ///< Scans handed over.
  std::int64_t inserted = 0;   ///< Scans inserted.
  std::int64_t dropped = 0;    ///< Scans refused because the previous one was not done.
  std::vector<double> insert_ms;  ///< Insertion times, ms (the newest, AddSample).
};

class OctomapWorker {
 public:
  /// Starts the thread (nice + 10).
  explicit OctomapWorker(OctomapMirror mirror);
  /// Finishes the scan under way, then joins the thread.
  ~OctomapWorker();
  OctomapWorker(const OctomapWorker&) = delete;
  OctomapWorker& operator=(const OctomapWorker&) = delete;

  /// Hands one scan (points in W, sensor origin p_WS) to the thread; false (counted as
  /// dropped) if it is still inserting the previous one: the mirror lags rather than queues.
  bool Submit(const Eigen::Vector3d& p_WS, std::span<const Eigen::Vector3f> p_WP);
  /// Waits until the scan under way is in, then writes the tree as a .bt (OctomapMirror::
  /// Save; throws std::runtime_error naming the path).
  void SaveWhenIdle(const std::string& path);
  OctomapWorkerStats stats() const;

 private:
  void Run();

  OctomapMirror mirror_;
  mutable std::mutex mutex_;
  std::condition_variable wake_, idle_;
  bool has_job_ = false, busy_ = false, stop_ = false;
  Eigen::Vector3d job_origin_W_ = Eigen::Vector3d::Zero();
  std::vector<Eigen::Vector3f> job_points_W_;
  OctomapWorkerStats stats_;
  std::thread thread_;
};

}  // namespace topay::mapper
