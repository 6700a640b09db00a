#pragma once
// Runs the LiDAR on a thread of its own, so that a 4-5 ms scan does not hold up the 500 Hz
// plant loop. Jobs (world updates and scan requests) are done strictly in the order given,
// with one sensor, so the scans are the same as the inline ones (same states, worlds and
// random draws in the same order); only when they are published changes (a few ms later).
// With `latest_scan_only` (the simulator in real time), a scan request drops the scan requests
// still waiting (world updates stay, in order): a thread that falls behind (a loaded machine)
// then delivers scans at most one scan time late, as a real LiDAR that skips frames, instead
// of a queue of ever older ones (seconds late under load, measured).

#include <condition_variable>
#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <mutex>
#include <thread>
#include <variant>
#include <vector>

#include "procs/sim/sim_sensors.h"

namespace topay::simproc {

class ScanWorker {
 public:
  /// With `on_done`, each finished scan is handed to it on the worker's thread (e.g. to
  /// convert and publish it there) instead of being kept for TakeCompleted.
  explicit ScanWorker(std::unique_ptr<ScanSensor> sensor, std::function<void(ScanResult&&)> on_done = nullptr,
                      bool latest_scan_only = false);
  /// Finishes the queued jobs, then joins the thread.
  ~ScanWorker();

  void SetWorld(std::vector<OrientedBox> boxes);
  void Request(const WholeBodyState& state, double t_s);
  /// The scans finished since the last call, in request order.
  std::vector<ScanResult> TakeCompleted();
  /// Waits until every queued job is done (tests, shutdown).
  void Drain();
  /// Jobs queued or running.
  int backlog() const;
  /// Scan requests dropped unscanned (latest_scan_only) since the start.
  std::int64_t dropped() const;

 private:
  struct ScanJob {
    WholeBodyState state;
    double t_s;
  };
  using Job = std::variant<std::vector<OrientedBox>, ScanJob>;
  void Run();

  std::unique_ptr<ScanSensor> sensor_;
  std::function<void(ScanResult&&)> on_done_;
  mutable std::mutex mutex_;
  std::condition_variable wake_, idle_;
  std::deque<Job> jobs_;
  std::vector<ScanResult> done_;
  int running_ = 0;
  bool latest_scan_only_ = false;
  std::int64_t dropped_ = 0;
  bool stop_ = false;
  std::thread thread_;
};

}  // namespace topay::simproc
